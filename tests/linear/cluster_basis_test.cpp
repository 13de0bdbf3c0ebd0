// cluster_basis (the block inverse iteration that gives a tight cluster of eigenvalues its
// orthonormal basis in TwistedModeIpr) against a dense Eigen eigensolver: on the clusters of
// small-ξ chains (light beads isolated among heavy ones), its columns must be orthonormal and span
// the subspace of Eigen's eigenvectors for those eigenvalues, to the subspace's own conditioning
// ε‖T‖ / gap; and an exactly degenerate pair must come out as two orthonormal vectors of it.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "granular/linear/detail/cluster_basis.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"

namespace granular {
namespace {

struct ClusterChain {
  std::vector<double> d, e;
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
};

ClusterChain cluster_chain(std::vector<double> d, std::vector<double> e) {
  const auto n = static_cast<Eigen::Index>(d.size());
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) t(i, i) = d[static_cast<std::size_t>(i)];
  for (Eigen::Index i = 0; i + 1 < n; ++i) t(i, i + 1) = t(i + 1, i) = e[static_cast<std::size_t>(i)];
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(t);
  return {std::move(d), std::move(e), es.eigenvalues(), es.eigenvectors()};
}

ClusterChain scaled_chain(double xi, std::uint64_t realization, std::size_t n) {
  const auto types = realization_configuration(Disorder::anderson, 0.5, n, 1, realization);
  const SymTridiagonal t = dynamical_matrix(make_chain(radii_of(types, 4.76e-3, xi), 10.0));
  const double scale = t.max_abs();
  std::vector<double> d, e;
  for (double x : t.diagonal) d.push_back(x / scale);
  for (double x : t.off_diagonal) e.push_back(x / scale);
  return cluster_chain(std::move(d), std::move(e));
}

/// Largest deviation of ZᵀZ from I, and 1 − the smallest cosine of the angles between span Z and
/// the reference eigenvectors [first, first + count).
std::pair<double, double> cluster_errors(const ClusterChain& c, const std::vector<double>& z, std::size_t first,
                                         std::size_t count) {
  const auto n = static_cast<Eigen::Index>(c.d.size()), k = static_cast<Eigen::Index>(count);
  const Eigen::Map<const Eigen::MatrixXd> basis(z.data(), n, k);
  const double orthonormality = (basis.transpose() * basis - Eigen::MatrixXd::Identity(k, k)).cwiseAbs().maxCoeff();
  const Eigen::MatrixXd overlap = c.vectors.middleCols(static_cast<Eigen::Index>(first), k).transpose() * basis;
  const double cosine = Eigen::JacobiSVD<Eigen::MatrixXd>(overlap).singularValues().minCoeff();
  return {orthonormality, 1 - cosine};
}

TEST(ClusterBasis, SpansTheDenseSolversSubspaceOnSmallXiClusters) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  std::size_t checked = 0;
  for (std::uint64_t r = 0; r < 4; ++r) {
    const ClusterChain c = scaled_chain(0.1, r, 400);
    const std::size_t n = c.d.size();
    const double norm = std::max(std::fabs(c.values[0]), std::fabs(c.values[static_cast<Eigen::Index>(n) - 1]));
    for (std::size_t k = 0; k < n;) {
      std::size_t end = k + 1;  // the solver's clusters: neighbours closer than 1e-10 max|λ|
      while (end < n &&
             c.values[static_cast<Eigen::Index>(end)] - c.values[static_cast<Eigen::Index>(end) - 1] < 1e-10 * norm)
        ++end;
      const std::size_t count = end - k;
      if (count >= 2) {
        double gap = INFINITY;  // to the rest of the spectrum
        if (k > 0) gap = c.values[static_cast<Eigen::Index>(k)] - c.values[static_cast<Eigen::Index>(k) - 1];
        if (end < n)
          gap = std::min(gap, c.values[static_cast<Eigen::Index>(end)] - c.values[static_cast<Eigen::Index>(end) - 1]);
        std::vector<double> lambda(c.values.data() + k, c.values.data() + end), z(n * count);
        detail::ClusterWork work;
        const double tolerance = 1e3 * static_cast<double>(n) * eps * norm * std::sqrt(static_cast<double>(count));
        ASSERT_TRUE(detail::cluster_basis(c.d.data(), c.e.data(), n, lambda.data(), count, tolerance, z.data(), work))
            << "r " << r << " cluster at " << k;
        const auto [orthonormality, angle] = cluster_errors(c, z, k, count);
        EXPECT_LE(orthonormality, 1e-13) << "r " << r << " cluster at " << k;
        // both bases are determined only to ~ε‖T‖/gap (Davis–Kahan), the reference's too
        EXPECT_LE(angle, std::max(1e-12, 1e3 * eps * norm / gap))
            << "r " << r << " cluster at " << k << " of " << count << ", gap " << gap / norm;
        ++checked;
      }
      k = end;
    }
  }
  EXPECT_GT(checked, 20u) << "ξ = 0.1 chains of 400 beads should hold clusters";
}

TEST(ClusterBasis, GivesAnExactlyDegeneratePairTwoOrthonormalVectors) {
  ClusterChain half = scaled_chain(0.3, 7, 30);
  std::vector<double> d = half.d, e = half.e;
  d.insert(d.end(), half.d.begin(), half.d.end());
  e.push_back(0.0);  // two copies, no bond between them: every eigenvalue exactly double
  e.insert(e.end(), half.e.begin(), half.e.end());
  const ClusterChain c = cluster_chain(d, e);
  for (std::size_t k : {0, 20, 58}) {
    std::vector<double> lambda = {c.values[static_cast<Eigen::Index>(k)], c.values[static_cast<Eigen::Index>(k) + 1]};
    std::vector<double> z(2 * c.d.size());
    detail::ClusterWork work;
    ASSERT_TRUE(detail::cluster_basis(c.d.data(), c.e.data(), c.d.size(), lambda.data(), 2, 1e-12, z.data(), work));
    const auto [orthonormality, angle] = cluster_errors(c, z, k, 2);
    EXPECT_LE(orthonormality, 1e-13) << "pair " << k;
    EXPECT_LE(angle, 1e-12) << "pair " << k;
  }
}

TEST(ClusterBasis, RefusesWhatItCannotDo) {
  const ClusterChain c = scaled_chain(0.5, 0, 10);
  std::vector<double> lambda(11, 1.0), z(11 * 10);
  detail::ClusterWork work;
  EXPECT_FALSE(detail::cluster_basis(c.d.data(), c.e.data(), 10, lambda.data(), 11, 1e-12, z.data(), work));
  EXPECT_FALSE(detail::cluster_basis(c.d.data(), c.e.data(), 10, lambda.data(), 0, 1e-12, z.data(), work));
  // a tolerance no iteration reaches: the caller is told (and falls back to dstein)
  std::vector<double> two = {c.values[3], c.values[4]};
  EXPECT_FALSE(detail::cluster_basis(c.d.data(), c.e.data(), 10, two.data(), 2, 0.0, z.data(), work));
}

}  // namespace
}  // namespace granular
