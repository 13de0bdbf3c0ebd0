// The many-shift Sturm sweeps of sturm_bisection.cpp (vector kernels of 8, 16 and 32 lanes, padded
// batches) against single-shift counts, and many-shift bisection against LAPACK's own bisection
// (dstebz) on random chains and on matrices with tight eigenvalue clusters.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "granular/linear/detail/lapack.hpp"
#include "granular/linear/detail/lapack_eigensolver.hpp"
#include "granular/linear/detail/sturm_bisection.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/tridiagonal_operator.hpp"
#include "granular/model/named_chains.hpp"

namespace granular {
namespace {

SymTridiagonal multishift_random_chain(Disorder disorder, std::size_t n, std::uint64_t seed) {
  return dynamical_matrix(random_chain(disorder, {.N = n, .q = 0.5, .xi = 0.5, .seed = seed}));
}

/// Two copies of one random block joined by a bond 1e-9 of the others: each eigenvalue of the
/// block appears twice, split by ~1e-9 · (its vector at the join)², down to exact degeneracy.
SymTridiagonal multishift_twin_blocks(std::size_t half, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(1.0, 3.0);
  SymTridiagonal t;
  t.diagonal.resize(2 * half);
  t.off_diagonal.resize(2 * half - 1);
  for (std::size_t i = 0; i < half; ++i) t.diagonal[i] = t.diagonal[2 * half - 1 - i] = 1e10 * u(rng);
  for (std::size_t i = 0; i + 1 < half; ++i) t.off_diagonal[i] = t.off_diagonal[2 * half - 2 - i] = -4e9 * u(rng);
  t.off_diagonal[half - 1] = -1e1;
  return t;
}

/// Wilkinson's W⁺(2k+1): diagonal |k − i|, off-diagonal 1, eigenvalues in pairs agreeing to ~1/k!.
SymTridiagonal multishift_wilkinson(int k) {
  SymTridiagonal t;
  for (int i = 0; i <= 2 * k; ++i) t.diagonal.push_back(std::abs(k - i));
  t.off_diagonal.assign(2 * static_cast<std::size_t>(k), 1.0);
  return t;
}

/// Eigenvalues il..iu (1-based) by LAPACK's dstebz to full precision.
std::vector<double> multishift_dstebz(const SymTridiagonal& t, int il, int iu) {
  const int n = static_cast<int>(t.size());
  std::vector<double> d = t.diagonal, e = t.off_diagonal, w(n), work(4 * n);
  std::vector<int> iblock(n), isplit(n), iwork(3 * n);
  int m = 0, nsplit = 0, info = 0;
  const double vl = 0, vu = 0, abstol = 2 * std::numeric_limits<double>::min();
  dstebz_("I", "E", &n, &vl, &vu, &il, &iu, &abstol, d.data(), e.data(), &m, &nsplit, w.data(), iblock.data(),
          isplit.data(), work.data(), iwork.data(), &info, 1, 1);
  EXPECT_EQ(info, 0);
  w.resize(m);
  return w;
}

/// Shifts that probe a count's edge cases: random ones across the spectrum, the eigenvalues
/// themselves and their neighbouring doubles, and exact repeats.
std::vector<double> multishift_probes(const SymTridiagonal& t, std::uint64_t seed) {
  const auto values = LapackEigensolver().solve(t, false).values;
  const auto [lo, hi] = gershgorin_bounds(t);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<double> s;
  for (int k = 0; k < 40; ++k) s.push_back(u(rng));
  for (Eigen::Index k = 0; k < values.size(); k += std::max<Eigen::Index>(1, values.size() / 30)) {
    const double v = values[k];
    s.push_back(v);
    s.push_back(std::nextafter(v, -std::numeric_limits<double>::infinity()));
    s.push_back(std::nextafter(v, std::numeric_limits<double>::infinity()));
  }
  s.push_back(s.front());
  s.push_back(lo - 1);
  s.push_back(hi + 1);
  return s;
}

TEST(ManyShiftCounts, EqualTheSingleShiftCountsExactlyForEveryBatchSize) {
  for (const auto& t :
       {multishift_random_chain(Disorder::anderson, 3001, 5), multishift_random_chain(Disorder::rdm2, 2000, 6),
        multishift_twin_blocks(700, 7), multishift_wilkinson(40)}) {
    const std::vector<double> probes = multishift_probes(t, 11);
    const TridiagonalOperator op(t);
    std::vector<long> alone(probes.size());
    for (std::size_t q = 0; q < probes.size(); ++q) {
      alone[q] = count_below_many(t, {probes[q]})[0];
#if !defined(__AVX512F__)  // the AVX-512 sweep divides by a refined reciprocal, the scalar count exactly
      EXPECT_EQ(alone[q], static_cast<long>(op.count_below(probes[q]))) << "shift " << probes[q];
#endif
    }
    // Batches of every size up to 40 (8-, 16- and 32-lane sweeps, padded), starting anywhere.
    for (std::size_t size = 1; size <= 40; ++size)
      for (std::size_t start = 0; start + size <= probes.size(); start += 7) {
        const std::vector<double> batch(probes.begin() + static_cast<long>(start),
                                        probes.begin() + static_cast<long>(start + size));
        const std::vector<long> together = count_below_many(t, batch);
        ASSERT_EQ(together.size(), size);
        for (std::size_t q = 0; q < size; ++q)
          ASSERT_EQ(together[q], alone[start + q]) << "batch of " << size << " from " << start << ", lane " << q;
      }
  }
}

TEST(ManyShiftBisection, EigenvaluesMatchDstebzOnRandomAndClusteredMatrices) {
  struct Probe {
    SymTridiagonal t;
    const char* what;
  };
  const std::vector<Probe> probes{{multishift_random_chain(Disorder::anderson, 4000, 8), "anderson"},
                                  {multishift_random_chain(Disorder::rdm1, 4000, 9), "rdm1"},
                                  {multishift_random_chain(Disorder::homogeneous, 3000, 1), "homogeneous"},
                                  {multishift_twin_blocks(1500, 10), "twin blocks"},
                                  {multishift_wilkinson(60), "wilkinson"}};
  for (const auto& [t, what] : probes) {
    const int n = static_cast<int>(t.size());
    const double scale = std::max(std::fabs(gershgorin_bounds(t).first), std::fabs(gershgorin_bounds(t).second));
    for (const auto& [first, last] : {std::pair{1, 30}, std::pair{n / 2 - 20, n / 2 + 21}, std::pair{n - 63, n}}) {
      const std::vector<double> lapack = multishift_dstebz(t, first, last);
      // Without a centre, with one amid the wanted eigenvalues, and with one far off (the first
      // sweep then probes the wrong place; the result may not change).
      const double mid = lapack[lapack.size() / 2];
      for (const double centre : {std::numeric_limits<double>::quiet_NaN(), mid, 0.5 * mid + 0.5 * scale}) {
        const std::vector<double> ours = bisect_eigenvalues(t, first, last, 1e-14, 0, nullptr, centre);
        ASSERT_EQ(ours.size(), lapack.size()) << what;
        for (std::size_t j = 0; j < ours.size(); ++j)
          EXPECT_NEAR(ours[j], lapack[j], 1e-13 * scale)
              << what << " eigenvalue " << first + static_cast<int>(j) << " centre " << centre;
      }
    }
  }
}

// With `nearest` = K, the bisection may stop lanes that K others are certainly nearer to the centre
// (in √λ): the K nearest and their index neighbours still reach full precision, and every stopped
// lane's value, a coarse midpoint, is farther from the centre than each of the K nearest.
TEST(ManyShiftBisection, OnlyTheNearestAndTheirNeighboursAreRefined) {
  for (const auto& [t, what] : {std::pair{multishift_random_chain(Disorder::anderson, 4000, 8), "anderson"},
                                std::pair{multishift_random_chain(Disorder::homogeneous, 3000, 1), "homogeneous"},
                                std::pair{multishift_twin_blocks(1500, 10), "twin blocks"}}) {
    const int n = static_cast<int>(t.size());
    const double scale = std::max(std::fabs(gershgorin_bounds(t).first), std::fabs(gershgorin_bounds(t).second));
    const int first = n / 2 - 21, last = n / 2 + 22;  // 44 lanes, as a nearest selection of 20 asks
    const std::vector<double> lapack = multishift_dstebz(t, first, last);
    const double centre = 0.5 * (lapack[20] + lapack[21]);
    constexpr std::size_t K = 20;
    std::vector<double> brackets;
    const std::vector<double> ours = bisect_eigenvalues(t, first, last, 1e-14, 0, &brackets, centre, K);
    ASSERT_EQ(ours.size(), lapack.size()) << what;
    auto distance = [&](double v) { return std::fabs(std::sqrt(v) - std::sqrt(centre)); };
    std::vector<std::size_t> order(lapack.size());
    for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return distance(lapack[a]) < distance(lapack[b]); });
    std::vector<bool> nearest(lapack.size(), false);
    for (std::size_t q = 0; q < K; ++q) nearest[order[q]] = true;
    std::size_t stopped = 0;
    for (std::size_t j = 0; j < ours.size(); ++j) {
      const bool needed = nearest[j] || (j > 0 && nearest[j - 1]) || (j + 1 < ours.size() && nearest[j + 1]);
      const double width = brackets[2 * j + 1] - brackets[2 * j];
      EXPECT_LE(brackets[2 * j], lapack[j] + 1e-13 * scale) << what << " lane " << j;
      EXPECT_GE(brackets[2 * j + 1], lapack[j] - 1e-13 * scale) << what << " lane " << j;
      if (needed) {
        EXPECT_NEAR(ours[j], lapack[j], 1e-13 * scale) << what << " lane " << j << " (wanted)";
        continue;
      }
      stopped += width > 1e-12 * scale;
      for (std::size_t q = 0; q < K; ++q)
        EXPECT_GT(distance(ours[j]), distance(ours[order[q]])) << what << " stopped lane " << j;
    }
    EXPECT_GT(stopped, 0u) << what << ": no lane was spared";
  }
}

}  // namespace
}  // namespace granular
