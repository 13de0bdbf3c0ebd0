// Where the covariant Lyapunov vectors live along the chain (participation, centre: the per-site
// share of ‖w‖², covariant_vectors.hpp), checked on a chain of two decoupled halves. With the bond
// between sites 3 and 4 of an 8-site DKG chain cut, the tangent map is block-diagonal. Only the left
// half is excited; the right half rests at x = 0, where its tangent dynamics is harmonic (all its
// exponents 0). So the Oseledets directions of the left half's clearly nonzero exponents ±λ_1, ±λ_2
// (0.033 and 0.014; its λ_3 is 4e-4 at T = 2000, too close to the 10 zeros to separate) lie in the
// left half exactly: a random start's right-half share decays relative to them as exp(−2 λ_2 T)
// (forward, for CLV_1, CLV_2) and C's columns converge as exp(−gap T_b) (backward, for CLV_15,
// CLV_16), ~1e-60 after the transients of 5000. What is left is rounding: amplitudes of 1e-15 in
// Q, a share of 1e-30 (measured: at most 9.7e-30), far below the bar of 1e-24. The reported centre
// and participation must say so too.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "granular/chaos/covariant_vectors.hpp"
#include "granular/chaos/lyapunov_spectrum.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/klein_gordon/klein_gordon.hpp"

namespace granular {
namespace {

// The share of ‖w‖² (time unit 1) on sites [first, last).
double clv_share(const State& w, std::size_t first, std::size_t last) {
  double part = 0, all = 0;
  for (std::size_t i = 0; i < w.u.size(); ++i) {
    const double e = w.u[i] * w.u[i] + w.v[i] * w.v[i];
    all += e;
    if (i >= first && i < last) part += e;
  }
  return part / all;
}

TEST(CovariantLocalization, VectorsOfTheExcitedHalfOfADecoupledChainLiveThere) {
  const std::size_t n = 8, half = 4;
  Chain chain = klein_gordon({.N = n, .W = 4, .seed = 5});
  chain.spring[half] = 0;  // bond between sites 3 and 4 (0-based): two independent 4-site chains
  const ForceLaw law = make_force_law(ForceLawKind::linear, chain);
  State start = block_energy_kick(chain, 0, half, 2.0, 3);
  const double tau = 0.05;
  const CovariantVectors clv = covariant_vectors(law, chain, saba2c(), tau, start,
                                                 {.vectors = 2 * n,
                                                  .orthonormalize_every = 10,
                                                  .forward_transient = 100000,
                                                  .backward_transient = 100000,
                                                  .time_unit = 1},
                                                 {0, 20000, 40000});
  std::printf("  growth rates:");
  for (double g : clv.growth_rates) std::printf(" %.4f", g);
  std::printf("\n");
  const std::size_t k = 2 * n, chaotic = 2;  // λ_1, λ_2 > 0 on the left half
  for (std::size_t s = 0; s < clv.time.size(); ++s) {
    std::printf("  t = %.0f:", clv.time[s]);
    for (std::size_t i = 0; i < k; ++i)
      std::printf(" %zu:%.1e/%.2f", i + 1, clv_share(clv.vectors[s][i], half, n), clv.centre[s][i]);
    std::printf("\n");
    for (std::size_t i = 0; i < k; ++i) {
      if (i >= chaotic && i < k - chaotic) continue;  // λ_3, the zeros, −λ_3: may mix both halves
      EXPECT_LT(clv_share(clv.vectors[s][i], half, n), 1e-24) << "sample " << s << ", CLV " << i + 1;
      EXPECT_LT(clv.centre[s][i], 3.0 + 1e-12) << "sample " << s << ", CLV " << i + 1;
      EXPECT_LE(clv.participation[s][i], 4.0 + 1e-12) << "sample " << s << ", CLV " << i + 1;
    }
  }
  // The left half is chaotic and its exponents pair up: the vectors above are not all neutral.
  EXPECT_GT(clv.growth_rates[chaotic - 1], 1e-3);
  EXPECT_LT(clv.growth_rates[k - chaotic], -1e-3);
}

}  // namespace
}  // namespace granular
