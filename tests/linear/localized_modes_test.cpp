// Eigenvectors of localized modes on windows of a long chain (detail/localized_modes.hpp) against
// the whole-chain lane inverse iteration on the same brackets, and the modes no window may take.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "granular/linear/detail/localized_modes.hpp"
#include "granular/linear/detail/sturm_bisection.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/linear/tridiagonal_operator.hpp"
#include "granular/model/named_chains.hpp"

namespace granular {
namespace {

DynamicalMatrix localized_test_chain(Disorder disorder, std::size_t n, std::uint64_t seed) {
  return dynamical_matrix(random_chain(disorder, {.N = n, .q = 0.5, .xi = 0.5, .seed = seed}));
}

/// Modes first..last bracketed as the bisect method does (isolated ones to 1e-7).
std::vector<double> localized_test_brackets(const SymTridiagonal& t, int first, int last, std::vector<double>& values) {
  std::vector<double> brackets;
  values = bisect_eigenvalues(t, first, last, 1e-14, 1e-7, &brackets);
  return brackets;
}

TEST(LocalizedModes, WindowVectorsEqualTheWholeChainSolve) {
  const DynamicalMatrix d = localized_test_chain(Disorder::anderson, 60000, 3);
  const int c = static_cast<int>(TridiagonalOperator(d).count_below(omega_squared_of_khz(15.0)));
  std::vector<double> values;
  const std::vector<double> brackets = localized_test_brackets(d, c - 10, c + 11, values);
  const std::size_t n = d.size(), m = values.size();
  Eigen::MatrixXd windowed(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
  const LocalizedModes local = solve_localized_modes(d, values, brackets, d.inverse_sqrt_mass, &windowed);

  std::vector<double> whole_values = values, ipr, residual;
  LaneOptions lanes;
  lanes.inverse_sqrt_mass = &d.inverse_sqrt_mass;
  lanes.ipr = &ipr;
  lanes.residual = &residual;
  const Eigen::MatrixXd whole = lane_inverse_iteration(d, whole_values, &brackets, lanes);
  const double norm = d.max_abs(), eps = std::numeric_limits<double>::epsilon();
  std::size_t solved = 0;
  for (std::size_t j = 0; j < m; ++j) {
    if (!local.solved[j]) continue;
    ++solved;
    EXPECT_NEAR(local.values[j], whole_values[j], 1e-13 * whole_values[j]) << "mode " << j;
    EXPECT_NEAR(local.ipr[j], ipr[j], 1e-8 * ipr[j]) << "mode " << j;
    EXPECT_LE(local.residual[j], 64 * eps * norm) << "mode " << j;
    double overlap = 0, norm2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
      overlap += windowed(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) *
                 whole(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
      norm2 += std::pow(windowed(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)), 2);
    }
    EXPECT_NEAR(norm2, 1.0, 1e-12) << "mode " << j;
    EXPECT_NEAR(std::fabs(overlap), 1.0, 1e-9) << "mode " << j;
  }
  // Localization lengths at 15 kHz are tens of beads: every mode fits a window here.
  EXPECT_EQ(solved, m);
}

TEST(LocalizedModes, BisectVectorsOfALongChainEqualLapacks) {
  // 20000 beads: the bisect method solves these modes on windows; dstemr solves the whole chain.
  const DynamicalMatrix d = localized_test_chain(Disorder::anderson, 20000, 5);
  SpectrumConfig config;
  config.vectors = true;
  config.method = SpectrumMethod::lapack;
  const Spectrum ref = spectrum(d, nearest(15.0, 12), config);
  config.method = SpectrumMethod::bisect;
  const Spectrum got = spectrum(d, nearest(15.0, 12), config);
  ASSERT_EQ(got.mode, ref.mode);
  for (std::size_t j = 0; j < got.size(); ++j) {
    EXPECT_NEAR(got.omega2[j], ref.omega2[j], 1e-10 * ref.omega2[j]);
    EXPECT_LE(got.residual[j], 1e-13);
    double overlap = 0;
    for (std::size_t i = 0; i < d.size(); ++i) overlap += got.vector(j)[i] * ref.vector(j)[i];
    EXPECT_NEAR(overlap, 1.0, 1e-8) << "mode " << got.mode[j];  // same sign convention (largest entry > 0)
  }
}

TEST(LocalizedModes, AnchorsFallInsideTheirModes) {
  const DynamicalMatrix d = localized_test_chain(Disorder::rdm1, 40000, 4);
  const int c = static_cast<int>(TridiagonalOperator(d).count_below(omega_squared_of_khz(20.0)));
  std::vector<double> values;
  const std::vector<double> brackets = localized_test_brackets(d, c - 5, c + 6, values);
  const std::vector<std::size_t> anchors = mode_anchors(d, brackets);
  std::vector<double> whole_values = values;
  const Eigen::MatrixXd whole = lane_inverse_iteration(d, whole_values, &brackets);
  for (std::size_t j = 0; j < values.size(); ++j) {
    Eigen::Index peak = 0;
    whole.col(static_cast<Eigen::Index>(j)).cwiseAbs().maxCoeff(&peak);
    // Right of the peak, by a few localization lengths at most.
    EXPECT_GE(static_cast<long>(anchors[j]), static_cast<long>(peak) - 16) << "mode " << j;
    EXPECT_LE(static_cast<long>(anchors[j]), static_cast<long>(peak) + 1024) << "mode " << j;
  }
}

TEST(LocalizedModes, ExtendedAndShortChainsAreLeftToTheWholeChainSolve) {
  // A homogeneous chain's modes span it: no window's residual can pass.
  const DynamicalMatrix h = localized_test_chain(Disorder::homogeneous, 20000, 1);
  const int c = static_cast<int>(TridiagonalOperator(h).count_below(omega_squared_of_khz(15.0)));
  std::vector<double> values;
  std::vector<double> brackets = localized_test_brackets(h, c - 3, c + 4, values);
  LocalizedModes local = solve_localized_modes(h, values, brackets, h.inverse_sqrt_mass, nullptr);
  EXPECT_EQ(std::count(local.solved.begin(), local.solved.end(), true), 0);
  EXPECT_EQ(local.values, values);
  // Too short for a window.
  const DynamicalMatrix s = localized_test_chain(Disorder::anderson, 5000, 2);
  brackets = localized_test_brackets(s, 100, 110, values);
  local = solve_localized_modes(s, values, brackets, s.inverse_sqrt_mass, nullptr);
  EXPECT_EQ(std::count(local.solved.begin(), local.solved.end(), true), 0);
}

}  // namespace
}  // namespace granular
