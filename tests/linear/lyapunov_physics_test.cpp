// Lyapunov exponents of disordered chains against physics they must reproduce: λ ∝ f² at low
// frequency (docs/physics.md, "The linear spectrum"), and the exponential decay of the eigenvectors of finite chains,
// found independently by full diagonalization.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "fixtures.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/linear/transfer_matrix.hpp"
#include "granular/model/chain.hpp"

namespace granular {
namespace {

TEST(LyapunovPhysics, AndersonChainLambdaGrowsAsFSquaredAtLowFrequency) {
  // Anderson chain (ξ = q = 0.5, F0 = 10 N; f1 = 18.09 kHz), one decade 0.3–3 kHz, N = 10⁷:
  // ℓ runs from ~12000 down to ~130 beads, so every point averages over ≥ 800 localization
  // lengths. Weighted least squares of ln λ on ln f with the segment errors; next-order
  // (f⁴) terms make the slope ~2.01 here and ~2.03 on 0.5–5 kHz.
  std::vector<double> f;
  for (int k = 0; k <= 10; ++k) f.push_back(0.3 * std::pow(10.0, k / 10.0));
  const auto scan =
      transfer_matrix_scan(*random_beads(Disorder::anderson, {.N = 10000000, .q = 0.5, .seed = 1, .realization = 0}), f);
  double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    ASSERT_GT(scan.lyapunov[k], 5 * scan.lyapunov_error[k]) << f[k] << " kHz";
    const double x = std::log(f[k]), y = std::log(scan.lyapunov[k]);
    const double w = std::pow(scan.lyapunov[k] / scan.lyapunov_error[k], 2);  // 1/var(ln λ)
    sw += w, sx += w * x, sy += w * y, sxx += w * x * x, sxy += w * x * y;
  }
  const double slope = (sw * sxy - sx * sy) / (sw * sxx - sx * sx);
  const double slope_error = std::sqrt(sw / (sw * sxx - sx * sx));
  EXPECT_NEAR(slope, 2.0, 0.05);
  EXPECT_LT(slope_error, 0.02);  // the fit resolves the exponent well inside the tolerance
}

// RDM1 (ξ = q = 0.5, F0 = 10 N): λ vanishes at the dimer resonance (docs/physics.md), predicted
// independently of the scan: at m1 ω² = 2 B11 the two-bead unit of a run of type-1 beads is −I, so a
// "1 1" dimer in the host passes a wave unchanged. There λ is consistent with 0 and falls with N
// (below the finite-size floor 10 ln N / N), while 0.5 kHz away, and in the Anderson chain at the
// same frequency, the chain localizes within ~100 beads.
TEST(LyapunovPhysics, Rdm1LambdaVanishesAtTheDimerResonance) {
  const Chain one = make_chain(std::vector<double>(3, fixtures::r1), 10.0);
  const double resonance = std::sqrt(2 * linear_stiffness(one)[1] / one.mass[0]) / (2 * std::numbers::pi) / 1e3;
  const std::vector<double> f{resonance - 0.5, resonance, resonance + 0.5};
  std::vector<double> at;
  for (std::size_t n : {100000u, 1000000u}) {
    const auto scan =
        transfer_matrix_scan(*random_beads(Disorder::rdm1, {.N = n, .q = 0.5, .seed = 1, .realization = 0}), f);
    std::printf("  N = %zu: lambda(f_r = %.4f kHz) = %.3e (floor ln N / N = %.3e); %.4f, %.4f at f_r -/+ 0.5 kHz\n", n,
                resonance, scan.lyapunov[1], std::log(double(n)) / double(n), scan.lyapunov[0], scan.lyapunov[2]);
    EXPECT_LT(scan.lyapunov[1], 10 * std::log(double(n)) / double(n));
    EXPECT_GT(scan.lyapunov[0], 0.01);
    EXPECT_GT(scan.lyapunov[2], 0.01);
    at.push_back(scan.lyapunov[1]);
  }
  EXPECT_LT(at[1], at[0]);  // vanishing in the limit, not a small constant
  const auto anderson =
      transfer_matrix_scan(*random_beads(Disorder::anderson, {.N = 100000, .q = 0.5, .seed = 1, .realization = 0}),
                           {resonance});
  EXPECT_GT(anderson.lyapunov[0], 0.05);
}

TEST(Long_LyapunovPhysics, EigenvectorsOfFiniteChainsDecayAtLambda) {
  // Modes of an Anderson chain (ξ = q = 0.5, N = 4000, seed 7, realization 0) from LAPACK, with
  // frequencies 6–14 kHz: ℓ ≈ 8–15 beads there, well localized (a tail of 18ℓ ≈ 200 beads fits
  // in the chain many times over) yet many beads per e-fold, so a slope is well defined. The
  // profile ln ‖(v_n, v_{n+1})‖ (the norm, free of the dips at nodes) is fitted by least squares
  // on a window fixed in advance — from 3ℓ to 18ℓ from the maximum, ℓ from the reference —
  // on each side that does not reach a wall; a window reaching the round-off floor (30 e-folds
  // below the maximum: LAPACK's eigenvectors are good to ~1e-15 of their largest entry) is
  // skipped (it happens to ~1 % of them).
  //
  // Reference: λ(f) at every mode's frequency from a 10⁶-bead chain of another realization.
  // The stated error: ln‖u‖ wanders like a random walk of variance σ² per bead around the
  // slope λ, and the scan's error gives σ² = N · lyapunov_error² (S segments of N/S beads);
  // a least-squares slope over L beads of such a walk has variance (6/5) σ²/L. The test
  // asks that z = (slope − λ)/that error be distributed as it says: mean 0, spread 1.
  const std::size_t n = 4000, reference_n = 1000000;
  const Chain chain = fixtures::random_chain(Disorder::anderson, n, 0.5, 0.5, 0);
  const Spectrum eig = spectrum(dynamical_matrix(chain), all_modes(), {.vectors = true});  // LAPACK dstevd
  std::vector<std::size_t> modes;
  std::vector<double> f;
  for (std::size_t k = 0; k < n; ++k)
    if (const double fk = eig.freq_khz[k]; fk >= 6 && fk <= 14) {
      modes.push_back(k);
      f.push_back(fk);
    }
  const auto reference =
      transfer_matrix_scan(*random_beads(Disorder::anderson, {.N = reference_n, .q = 0.5, .seed = 7, .realization = 1}),
                           f);

  std::vector<double> z;
  int skipped_floor = 0;
  for (std::size_t j = 0; j < modes.size(); ++j) {
    std::vector<double> profile(n - 1);
    const auto w = eig.vector(modes[j]);
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const double a = w[i] * std::sqrt(chain.inverse_mass[i]);
      const double b = w[i + 1] * std::sqrt(chain.inverse_mass[i + 1]);
      profile[i] = 0.5 * std::log(a * a + b * b);
    }
    const long centre = std::max_element(profile.begin(), profile.end()) - profile.begin();
    const double ell = 1 / reference.lyapunov[j], top = profile[centre];
    const long start = static_cast<long>(std::ceil(3 * ell)), length = static_cast<long>(std::ceil(15 * ell));
    for (long side : {-1L, 1L}) {
      const long first = centre + side * start, last = centre + side * (start + length - 1);
      if (std::min(first, last) < 0 || std::max(first, last) >= static_cast<long>(n) - 1) continue;
      double sx = 0, sy = 0, sxx = 0, sxy = 0, lowest = top;
      for (long d = start; d < start + length; ++d) {
        const double y = profile[centre + side * d], x = static_cast<double>(d);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
        lowest = std::min(lowest, y);
      }
      if (lowest < top - 30) {
        ++skipped_floor;
        continue;
      }
      const double m = static_cast<double>(length);
      const double decay = -(m * sxy - sx * sy) / (m * sxx - sx * sx);
      const double sigma2 = static_cast<double>(reference_n) * std::pow(reference.lyapunov_error[j], 2);
      const double error = std::sqrt(1.2 * sigma2 / m + std::pow(reference.lyapunov_error[j], 2));
      z.push_back((decay - reference.lyapunov[j]) / error);
    }
  }
  ASSERT_GT(z.size(), 1000u);
  EXPECT_LT(skipped_floor, static_cast<int>(z.size() / 20));
  double mean = 0, square = 0;
  std::size_t within3 = 0;
  for (double v : z) mean += v, square += v * v, within3 += std::fabs(v) < 3;
  mean /= static_cast<double>(z.size());
  const double spread = std::sqrt(square / static_cast<double>(z.size()) - mean * mean);
  // Neighbouring modes share disorder, so z values are correlated and the mean's error is larger
  // than 1/√K (≈ 0.03): allow 0.25. A λ off by 10 % would shift the mean by ~0.4.
  EXPECT_NEAR(mean, 0.0, 0.25) << z.size() << " tails";
  EXPECT_NEAR(spread, 1.0, 0.25);
  EXPECT_GT(static_cast<double>(within3) / static_cast<double>(z.size()), 0.98);
}

}  // namespace
}  // namespace granular
