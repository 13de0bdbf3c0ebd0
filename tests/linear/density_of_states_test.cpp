// Node counting (Dean's method) against the full LAPACK spectrum, the analytic homogeneous
// chain, and the DOS by differencing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fixtures.hpp"
#include "granular/error.hpp"
#include "granular/linear/density_of_states.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"

namespace granular {
namespace {

std::vector<double> grid(double lo, double hi, double step) {
  std::vector<double> f;
  for (long k = 0; lo + static_cast<double>(k) * step <= hi + 1e-9; ++k)
    f.push_back(lo + static_cast<double>(k) * step);
  return f;
}

/// Compares node counts with the eigenvalues of the same chain (LAPACK, dstevd) at every grid
/// frequency whose ω² is not within 1e-9 relative of an eigenvalue (there rounding decides).
/// The grid runs from 0 to 5 % above the highest mode in 10⁴ steps.
void expect_counts_match_lapack(const BeadSource& source, const Chain& chain, const std::string& what) {
  const std::vector<double> omega2 = spectrum(dynamical_matrix(chain)).omega2;  // LAPACK dstevd
  ASSERT_TRUE(std::is_sorted(omega2.begin(), omega2.end()));
  const double top = 1.05 * frequency_khz(omega2.back());
  const std::vector<double> f = grid(0, top, top / 10000);
  const std::vector<std::int64_t> counts = count_modes_below(source, f);
  std::size_t compared = 0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    const double w2 = std::pow(2 * std::numbers::pi * 1e3 * f[k], 2);
    const auto below = std::lower_bound(omega2.begin(), omega2.end(), w2);
    const bool near = (below != omega2.end() && *below - w2 <= 1e-9 * w2) ||
                      (below != omega2.begin() && w2 - *(below - 1) <= 1e-9 * w2);
    if (near) continue;
    EXPECT_EQ(counts[k], below - omega2.begin()) << what << " at " << f[k] << " kHz";
    ++compared;
  }
  EXPECT_GT(compared, f.size() * 99 / 100) << what;
  EXPECT_EQ(counts.front(), 0) << what;
  EXPECT_EQ(counts.back(), static_cast<std::int64_t>(chain.size())) << what;
}

TEST(Long_DensityOfStates, NodeCountsAreTheLapackCountsForEveryDisorder) {
  const std::size_t n = 2000;
  for (Disorder kind : {Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2})
    for (double xi : {0.5, 0.2}) {
      const auto source = random_beads(kind, {.N = n, .q = 0.5, .xi = xi, .seed = 7, .realization = 0});
      const Chain chain = fixtures::random_chain(kind, n, xi, 0.5, 0);
      expect_counts_match_lapack(*source, chain, to_string(kind) + " xi=" + std::to_string(xi));
    }
}

TEST(DensityOfStates, NodeCountsOfAnyChainAreTheLapackCounts) {
  // A polydisperse chain (radii 2–6 mm) with a small fixed bead as the left wall: only a Chain
  // describes it.
  ChainSpec spec;
  for (int i = 0; i < 1500; ++i) spec.radii.push_back(2e-3 + 4e-3 * std::fabs(std::sin(1.7 * i * i + 0.3 * i)));
  spec.materials = {steel};
  spec.left_wall.radius = 1e-3;
  spec.precompression = 4;
  const Chain chain = make_chain(spec);
  expect_counts_match_lapack(*chain_beads(chain), chain, "polydisperse");
}

TEST(DensityOfStates, HomogeneousChainCountsAreAnalytic) {
  // Bulk walls: f_k = f1 sin(kπ / (2(N+1))), so the modes below f number ⌊(2(N+1)/π) asin(f/f1)⌋.
  const std::size_t n = 1000000;
  const Chain chain = fixtures::homogeneous_bulk_walls(n);
  const double b = linear_stiffness(chain)[1];
  const double f1 = std::sqrt(4 * b / chain.mass[0]) / (2 * std::numbers::pi) * 1e-3;
  const std::vector<double> f = grid(0.05, 18.05, 0.1);
  const auto counts = count_modes_below(*chain_beads(chain), f);
  for (std::size_t k = 0; k < f.size(); ++k) {
    const double x = f[k] < f1 ? 2.0 * (n + 1) / std::numbers::pi * std::asin(f[k] / f1) : double(n);
    if (std::fabs(x - std::round(x)) < 1e-6) continue;  // on an eigenvalue
    EXPECT_EQ(counts[k], static_cast<std::int64_t>(std::floor(x))) << f[k] << " kHz";
  }
  // DOS by differencing → (2/π) / sqrt(f1² − f²) per bead per kHz in the limit.
  const auto dos = density_of_states(f, integrated_density_of_states(counts, n));
  double worst = 0;
  for (std::size_t k = 1; k + 1 < f.size() && f[k + 1] < 0.9 * f1; ++k) {
    const double exact = 2 / std::numbers::pi / std::sqrt(f1 * f1 - f[k] * f[k]);
    worst = std::max(worst, std::fabs(dos[k] / exact - 1));
  }
  EXPECT_LT(worst, 1e-3);  // measured 3.5e-4: the ±1/N steps of the IDOS over 0.2 kHz and O(h²)
}

TEST(DensityOfStates, DifferencingIsCentralInsideAndOneSidedAtTheEnds) {
  const std::vector<double> f{0, 0.5, 1, 2, 4};
  std::vector<double> idos;
  for (double x : f) idos.push_back(x * x);  // central differences of x² at the midpoint of a symmetric pair are exact
  const auto dos = density_of_states(f, idos);
  EXPECT_DOUBLE_EQ(dos[0], 0.5);  // (0.25 − 0) / 0.5
  EXPECT_DOUBLE_EQ(dos[1], 1.0);  // (1 − 0) / 1
  EXPECT_DOUBLE_EQ(dos[2], (4 - 0.25) / 1.5);
  EXPECT_DOUBLE_EQ(dos[4], (16 - 4) / 2.0);
  EXPECT_TRUE(std::isnan(density_of_states({3}, {0.1})[0]));
  EXPECT_THROW(density_of_states({1, 1}, {0, 0}), InvalidInput);
  EXPECT_THROW(density_of_states({2, 1}, {0, 0}), InvalidInput);
  EXPECT_EQ(integrated_density_of_states({0, 3, 8}, 8), (std::vector<double>{0, 0.375, 1}));
}

}  // namespace
}  // namespace granular
