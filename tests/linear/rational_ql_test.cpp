// rational_ql_lanes (many chains' QL iterations in vector lanes, TwistedModeIpr's eigenvalue
// phase) against its scalar reference rational_ql, bit for bit, on batches that make lanes finish
// at different times and take new chains: mixed N (2 to 300, no multiple of the lane count),
// every disorder kind at small and large ξ (clustered and spread spectra), matrices that split
// exactly, diagonal ones, and one that never converges (NaN) among good ones. And both against
// independent eigenvalues: LAPACK's dsterf and the uniform chain's closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "granular/linear/detail/lapack.hpp"
#include "granular/linear/detail/rational_ql.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"

namespace granular {
namespace {

/// One test matrix: diagonal and squared off-diagonal.
struct QlMatrix {
  std::vector<double> d, e2;
};

QlMatrix ql_matrix_of(Disorder kind, double q, double xi, std::size_t n, std::uint64_t realization) {
  const auto types = realization_configuration(kind, q, n, 17, realization);
  const SymTridiagonal t = dynamical_matrix(make_chain(radii_of(types, 4.76e-3, xi), 10.0));
  const double scale = t.max_abs();
  QlMatrix m;
  for (double x : t.diagonal) m.d.push_back(x / scale);
  for (double x : t.off_diagonal) m.e2.push_back((x / scale) * (x / scale));
  return m;
}

/// A batch whose lanes finish at different times: more chains than lanes, N from 2 to 300.
std::vector<QlMatrix> ql_batch() {
  std::vector<QlMatrix> out;
  const Disorder kinds[] = {Disorder::anderson, Disorder::rdm1, Disorder::rdm2, Disorder::homogeneous};
  const std::size_t sizes[] = {100, 2, 37, 300, 3, 100, 5, 64, 211, 100};
  for (std::uint64_t r = 0; r < 40; ++r) {
    const Disorder kind = kinds[r % 4];
    const bool dimers = kind == Disorder::rdm1 || kind == Disorder::rdm2;
    const std::size_t n = sizes[r % 10] + (dimers && sizes[r % 10] % 2 == 1);
    out.push_back(ql_matrix_of(kind, r % 3 == 0 ? 0.2 : 0.5, 0.1 + 0.09 * static_cast<double>(r % 11), n, r));
  }
  QlMatrix split = ql_matrix_of(Disorder::anderson, 0.5, 0.3, 90, 99);  // three exact blocks
  split.e2[29] = split.e2[59] = 0;
  out.insert(out.begin() + 7, split);
  QlMatrix diagonal = ql_matrix_of(Disorder::anderson, 0.5, 0.3, 20, 98);
  std::fill(diagonal.e2.begin(), diagonal.e2.end(), 0.0);
  out.insert(out.begin() + 20, diagonal);
  return out;
}

std::vector<detail::QlChain> ql_chains(std::vector<QlMatrix>& matrices) {
  std::vector<detail::QlChain> chains;
  for (QlMatrix& m : matrices) chains.push_back({m.d.data(), m.e2.data(), m.d.size()});
  return chains;
}

TEST(RationalQl, LanesEqualTheScalarIterationBitForBit) {
  std::vector<QlMatrix> scalar = ql_batch(), lanes = ql_batch();
  std::vector<detail::QlChain> one = ql_chains(scalar), many = ql_chains(lanes);
  for (detail::QlChain& c : one) detail::rational_ql(c);
  detail::QlLaneWork work;
  detail::rational_ql_lanes(many, work);
  ASSERT_GT(many.size(), 2 * detail::ql_lane_count);  // lanes take new chains
  for (std::size_t i = 0; i < many.size(); ++i) {
    EXPECT_TRUE(one[i].converged) << "chain " << i;
    EXPECT_EQ(many[i].converged, one[i].converged) << "chain " << i;
    EXPECT_EQ(lanes[i].d, scalar[i].d) << "chain " << i << ", N = " << scalar[i].d.size();
  }
  // the same work again, reused, in another grouping
  std::vector<QlMatrix> again = ql_batch();
  std::vector<detail::QlChain> regrouped = ql_chains(again);
  for (std::size_t first = 0; first < regrouped.size(); first += 5)
    detail::rational_ql_lanes(std::span(regrouped).subspan(first, std::min<std::size_t>(5, regrouped.size() - first)),
                              work);
  for (std::size_t i = 0; i < regrouped.size(); ++i) EXPECT_EQ(again[i].d, scalar[i].d) << "chain " << i;
}

TEST(RationalQl, AgreesWithLapackDsterf) {
  std::vector<QlMatrix> ours = ql_batch();
  std::vector<detail::QlChain> chains = ql_chains(ours);
  detail::QlLaneWork work;
  detail::rational_ql_lanes(chains, work);
  std::vector<QlMatrix> theirs = ql_batch();
  for (std::size_t i = 0; i < ours.size(); ++i) {
    std::vector<double> d = theirs[i].d, e;
    for (double x : theirs[i].e2) e.push_back(std::sqrt(x));
    const int n = static_cast<int>(d.size());
    int info = 0;
    dsterf_(&n, d.data(), e.data(), &info);
    ASSERT_EQ(info, 0);
    std::vector<double> mine = ours[i].d;
    std::sort(mine.begin(), mine.end());
    for (std::size_t k = 0; k < d.size(); ++k)  // both backward stable: ~ε‖T‖ = ε absolute
      EXPECT_NEAR(mine[k], d[k], 50 * n * std::numeric_limits<double>::epsilon()) << "chain " << i << " mode " << k;
  }
}

TEST(RationalQl, UniformChainHasItsClosedFormSpectrum) {
  for (std::size_t n : {2, 7, 100, 333}) {
    std::vector<QlMatrix> m(3);
    for (QlMatrix& x : m) {
      x.d.assign(n, 2.0);
      x.e2.assign(n - 1, 1.0);
    }
    std::vector<detail::QlChain> chains = ql_chains(m);
    detail::QlLaneWork work;
    detail::rational_ql_lanes(chains, work);
    std::vector<double> got = m[2].d;
    std::sort(got.begin(), got.end());
    for (std::size_t k = 0; k < n; ++k) {
      const double exact = 2 - 2 * std::cos(static_cast<double>(k + 1) * std::numbers::pi / static_cast<double>(n + 1));
      EXPECT_NEAR(got[k], exact, 1e-14 * static_cast<double>(n)) << "N = " << n << ", k = " << k;
    }
  }
}

TEST(RationalQl, AChainThatCannotConvergeFailsAloneInItsBatch) {
  std::vector<QlMatrix> scalar = ql_batch(), lanes = ql_batch();
  for (auto* batch : {&scalar, &lanes}) (*batch)[5].e2[3] = std::numeric_limits<double>::quiet_NaN();
  std::vector<detail::QlChain> one = ql_chains(scalar), many = ql_chains(lanes);
  for (detail::QlChain& c : one) detail::rational_ql(c);
  detail::QlLaneWork work;
  detail::rational_ql_lanes(many, work);
  for (std::size_t i = 0; i < many.size(); ++i) {
    EXPECT_EQ(many[i].converged, i != 5) << "chain " << i;
    EXPECT_EQ(one[i].converged, i != 5) << "chain " << i;
    if (i != 5) {
      EXPECT_EQ(lanes[i].d, scalar[i].d) << "chain " << i;
    }
  }
}

}  // namespace
}  // namespace granular
