// The transfer matrices of a chain with on-site springs (the quasiperiodic chain S1, linearized:
// the Aubry–André model with hopping K and on-site amplitude λ k0). Checked against the dense
// spectrum (Dean's node count is exact) and against the Aubry–André Lyapunov exponent
// γ = ln(λ k0 / 2K) above the transition, 0 inside the bands below it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/linear/transfer_matrix.hpp"
#include "granular/model/chain_recipe.hpp"

namespace granular {
namespace {

ChainRecipe onsite_transfer_recipe(double lambda, std::size_t n) {
  ChainRecipe r{.N = n, .F0 = 10};
  r.source = Quasiperiodic{.kind = Quasiperiodic::Kind::s1, .modulation = lambda, .phase = 0.4};
  return r;
}

// One thread: the scans here are small, and the result does not depend on it.
TransferMatrixConfig onsite_transfer_config(std::size_t segments = 32) {
  TransferMatrixConfig c;
  c.segments = segments;
  c.threads = 1;
  return c;
}

TEST(OnsiteTransferMatrix, NodeCountIsTheDenseSpectrumCount) {
  // Frequencies halfway between consecutive eigenfrequencies of the same 377-bead chain: the count
  // below each must be exact. Without the springs every mode moves (ω² shifts by ≈ k0/m).
  const ChainRecipe r = onsite_transfer_recipe(0.6, 377);
  const Spectrum s = spectrum(dynamical_matrix(r.chain(0)));
  std::vector<double> f;
  for (std::size_t j = 0; j + 1 < s.size(); j += 7) f.push_back(0.5 * (s.freq_khz[j] + s.freq_khz[j + 1]));
  const TransferMatrixScan scan = transfer_matrix_scan(*r.beads(0), f, onsite_transfer_config(4));
  for (std::size_t k = 0; k < f.size(); ++k)
    EXPECT_EQ(scan.modes_below[k], static_cast<std::int64_t>(7 * k + 1)) << f[k] << " kHz";
}

// Eigenfrequencies (kHz) of a short chain with the same β and φ: points inside the spectrum of
// the long one, across it.
std::vector<double> onsite_transfer_frequencies(double lambda) {
  const Spectrum s = spectrum(dynamical_matrix(onsite_transfer_recipe(lambda, 610).chain(0)));
  std::vector<double> f;
  for (std::size_t j = 30; j < 600; j += 30) f.push_back(s.freq_khz[j]);
  return f;
}

TEST(OnsiteTransferMatrix, AboveTheTransitionLambdaIsTheAubryAndreValue) {
  // λ k0 > 2K (k0 = 4K): γ = ln(λ k0 / 2K) = ln 2λ at every frequency in the spectrum. Over
  // 2·10⁵ beads the finite-size error of the mean of a localized recursion is ~1/(γ N) ≤ 1e-4;
  // measured ≤ 1.7e-4, bound 1e-3.
  for (double lambda : {0.55, 0.7, 0.9}) {
    const ChainRecipe r = onsite_transfer_recipe(lambda, 200000);
    const double expected = std::log(lambda * r.as<Quasiperiodic>()->k0 / 2);
    const auto f = onsite_transfer_frequencies(lambda);
    const TransferMatrixScan scan = transfer_matrix_scan(*r.beads(0), f, onsite_transfer_config());
    double worst = 0;
    for (std::size_t k = 0; k < f.size(); ++k) {
      worst = std::max(worst, std::abs(scan.lyapunov[k] - expected));
      EXPECT_NEAR(scan.lyapunov[k], expected, 1e-3) << "lambda " << lambda << " at " << f[k] << " kHz";
    }
    std::printf("  lambda = %.2f: ln(lambda k0/2K) = %.4f, max |gamma - it| over %zu frequencies = %.2e\n", lambda,
                expected, f.size(), worst);
  }
}

TEST(OnsiteTransferMatrix, BelowTheTransitionLambdaVanishesInTheBands) {
  // λ k0 < 2K: every state is extended, γ → 0 as N grows inside the bands. Frequencies of a short
  // chain can sit in the long chain's gaps (dense, most of them tiny), where γ > 0; so the claim
  // is about most frequencies: the median γ is below 1e-3 and falls with N.
  for (double lambda : {0.2, 0.4}) {
    const auto f = onsite_transfer_frequencies(lambda);
    std::vector<double> median;
    for (std::size_t n : {10000, 160000}) {
      const TransferMatrixScan scan =
          transfer_matrix_scan(*onsite_transfer_recipe(lambda, n).beads(0), f, onsite_transfer_config());
      std::vector<double> g = scan.lyapunov;
      std::nth_element(g.begin(), g.begin() + static_cast<std::ptrdiff_t>(g.size() / 2), g.end());
      median.push_back(g[g.size() / 2]);
    }
    std::printf("  lambda = %.2f: median gamma %.2e (N = 1e4), %.2e (N = 1.6e5)\n", lambda, median[0], median[1]);
    EXPECT_LT(median[1], 1e-3) << lambda;
    EXPECT_LT(median[1], 0.5 * median[0]) << lambda;
  }
}

}  // namespace
}  // namespace granular
