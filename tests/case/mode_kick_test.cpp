// Mode-shaped kicks: the chain started in one linear mode stays in it — exactly
// under the linear force law (a splitting scheme applied to a linear system is a polynomial in
// M^{-1}K, so it keeps every eigenspace), and to within the nonlinearity at small Hertz amplitude.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "granular/case/mode_kick.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/error.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/study/transport_study.hpp"

namespace granular {
namespace {

struct Extremes {
  double min_fraction = 1, ipr_min = 1, ipr_max = 0;
};

/// Integrates the kick for `steps` steps of 1 µs, recording the mode's energy fraction and the
/// amplitude P⁻¹ after every step.
Extremes follow(const Chain& chain, ForceLawKind kind, const ModeKickResult& k, std::size_t steps) {
  const DynamicalMatrix d = dynamical_matrix(chain);
  const ForceLaw law = make_force_law(kind, chain);
  auto p = make_splitting_propagator(law, chain, saba2c(), 1e-6, k.initial, {.enabled = false});
  Extremes e;
  for (std::size_t s = 0; s < steps; ++s) {
    p->advance(1);
    const State state = p->state();
    e.min_fraction = std::min(e.min_fraction, mode_energy_fraction(d, k.vector, k.omega2, state));
    const double ipr = mode_amplitude_ipr(state, k.omega2);
    e.ipr_min = std::min(e.ipr_min, ipr);
    e.ipr_max = std::max(e.ipr_max, ipr);
  }
  return e;
}

Chain test_chain() { return anderson({.N = 100, .seed = 3}); }

TEST(ModeKick, TheInitialStateIsTheModesDisplacementShape) {
  const Chain chain = test_chain();
  const ModeKickResult k = mode_kick(chain, ForceLawKind::hertz, {.mode = 90, .amplitude = 1e-9});
  const Spectrum all = spectrum(dynamical_matrix(chain), all_modes(), {.vectors = true});
  EXPECT_EQ(k.mode, 90u);
  EXPECT_NEAR(k.freq_khz, all.freq_khz[89], 1e-9 * all.freq_khz[89]);
  EXPECT_NEAR(k.ipr, all.ipr[89], 1e-9);
  EXPECT_NEAR(mode_amplitude_ipr(k.initial, k.omega2), all.ipr[89], 1e-9);  // v = 0: A_n = |u_n|
  EXPECT_DOUBLE_EQ(*std::max_element(k.initial.u.begin(), k.initial.u.end(),
                                     [](double a, double b) { return std::abs(a) < std::abs(b); }) *
                       (k.initial.u[k.peak_site] < 0 ? -1 : 1),
                   1e-9);
  // u ∝ M^{-1/2} w, not w: the ratio u_n / w_n is a constant times m_n^{-1/2}.
  const DynamicalMatrix d = dynamical_matrix(chain);
  const double scale = k.initial.u[k.peak_site] / (all.vector(89)[k.peak_site] * d.inverse_sqrt_mass[k.peak_site]);
  for (std::size_t n = 0; n < chain.size(); ++n) {
    if (std::abs(all.vector(89)[n]) < 1e-3) continue;
    EXPECT_NEAR(k.initial.u[n] / (all.vector(89)[n] * d.inverse_sqrt_mass[n]), scale, 1e-6 * std::abs(scale));
  }
  EXPECT_NEAR(mode_energy_fraction(d, k.vector, k.omega2, k.initial), 1.0, 1e-12);
}

TEST(ModeKick, NearestFrequencyPicksTheNearestMode) {
  const Chain chain = test_chain();
  const Spectrum all = spectrum(dynamical_matrix(chain));
  const double target = 0.3 * all.freq_khz[40] + 0.7 * all.freq_khz[41];  // nearer mode 42
  const ModeKickResult k = mode_kick(chain, ForceLawKind::hertz, {.near_khz = target, .amplitude = 1e-9});
  EXPECT_EQ(k.mode, 42u);
}

TEST(ModeKick, EnergyIsMetUnderEveryForceLaw) {
  const Chain chain = test_chain();
  for (ForceLawKind kind : {ForceLawKind::hertz, ForceLawKind::fpu, ForceLawKind::linear}) {
    const ModeKickResult k = mode_kick(chain, kind, {.mode = 20, .energy = 1.16e-7});
    EXPECT_NEAR(k.energy, 1.16e-7, 1e-13 * 1.16e-7) << to_string(kind);
    EXPECT_NEAR(total_energy(make_force_law(kind, chain), chain, k.initial), 1.16e-7, 1e-13 * 1.16e-7);
  }
  // Linear law: H = ½ ω² Σ m u² exactly (v = 0, u in one mode), so the amplitude is analytic.
  const ModeKickResult k = mode_kick(chain, ForceLawKind::linear, {.mode = 20, .energy = 1.16e-7});
  double mass_norm = 0;
  for (std::size_t n = 0; n < chain.size(); ++n) mass_norm += chain.mass[n] * std::pow(k.initial.u[n] / k.amplitude, 2);
  EXPECT_NEAR(k.amplitude, std::sqrt(2 * 1.16e-7 / (k.omega2 * mass_norm)), 1e-12 * k.amplitude);
}

TEST(ModeKick, TheLinearForceLawKeepsTheModeExactly) {
  const Chain chain = test_chain();
  for (long mode : {5L, 95L}) {  // an extended and a localized mode
    const ModeKickResult k = mode_kick(chain, ForceLawKind::linear, {.mode = mode, .energy = 1e-7});
    const Extremes e = follow(chain, ForceLawKind::linear, k, 2000);
    EXPECT_GT(e.min_fraction, 1 - 1e-12) << "mode " << mode;
    EXPECT_LT(e.ipr_max - e.ipr_min, 1e-12) << "mode " << mode;
    EXPECT_NEAR(e.ipr_min, k.ipr, 1e-9);
  }
}

TEST(ModeKick, ASmallHertzKickStaysInItsMode) {
  const Chain chain = test_chain();
  for (long mode : {5L, 95L}) {
    // 1 pm: ε = a/Δ ~ 1e-6, where the Hertz force is linear to a part in a million.
    const ModeKickResult k = mode_kick(chain, ForceLawKind::hertz, {.mode = mode, .amplitude = 1e-12});
    const Extremes e = follow(chain, ForceLawKind::hertz, k, 2000);  // T = 2 ms
    EXPECT_GT(e.min_fraction, 0.999) << "mode " << mode;
    EXPECT_LT(e.ipr_max - e.ipr_min, 1e-6) << "mode " << mode;
    // What moves P⁻¹ of the localized mode is the nonlinearity: its swing is proportional to the
    // amplitude. (The extended mode's strains are smaller: its swing, ~5e-10, is the round-off of
    // the Hertz force, a difference of O(F0) terms, which does not shrink with the amplitude.)
    if (mode == 95) {
      const ModeKickResult tenth = mode_kick(chain, ForceLawKind::hertz, {.mode = mode, .amplitude = 1e-13});
      const Extremes f = follow(chain, ForceLawKind::hertz, tenth, 2000);
      const double ratio = (e.ipr_max - e.ipr_min) / (f.ipr_max - f.ipr_min);
      EXPECT_GT(ratio, 8);
      EXPECT_LT(ratio, 12);
    }
  }
}

TEST(ModeKick, ALargeHertzKickLeavesItsMode) {  // the converse: the checks above can fail
  const Chain chain = test_chain();
  const ModeKickResult k = mode_kick(chain, ForceLawKind::hertz, {.mode = 95, .amplitude = 2e-6});
  const Extremes e = follow(chain, ForceLawKind::hertz, k, 2000);
  EXPECT_LT(e.min_fraction, 0.999);
  EXPECT_GT(e.ipr_max - e.ipr_min, 1e-6 * k.ipr);
}

TEST(ModeKick, BadKicksNameTheirParameter) {
  const Chain chain = test_chain();
  const auto parameter_of = [&](const ModeKick& kick) {
    try {
      mode_kick(chain, ForceLawKind::hertz, kick);
    } catch (const InvalidInput& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  EXPECT_EQ(parameter_of({.amplitude = 1e-9}), "mode");                             // neither selector
  EXPECT_EQ(parameter_of({.mode = 3, .near_khz = 10, .amplitude = 1e-9}), "mode");  // both
  EXPECT_EQ(parameter_of({.mode = 101, .amplitude = 1e-9}), "mode");
  EXPECT_EQ(parameter_of({.mode = 3}), "amplitude");
  EXPECT_EQ(parameter_of({.mode = 3, .energy = -1}), "energy");
  EXPECT_EQ(parameter_of({.mode = 3, .energy = 1e6}), "energy");  // beads would overlap first
  EXPECT_THROW(mode_kick(anderson({.N = 100, .F0 = 0}), ForceLawKind::hertz, {.mode = 3, .amplitude = 1e-9}),
               InvalidInput);
}

TEST(ModeKick, TransportCaseRunsAModeKick) {
  TransportCase c;
  c.chain.N = 100;
  c.site = 51;
  c.kick = Kick::mode;
  c.mode = {.near_khz = 30, .energy = 1e-7};
  c.dynamics.integration.duration = 1e-4;
  c.fit = false;
  c.realizations = 1;
  validate(c);
  const KickedChain kicked = kick(c, anderson({.N = 100}));
  EXPECT_NEAR(kicked.mode.energy, 1e-7, 1e-13);
  EXPECT_NEAR(kicked.mode.freq_khz, 30, 2);
  EXPECT_EQ(describe(c)["ic"], "mode");
  EXPECT_EQ(describe(c)["near_khz"], 30.0);
}

}  // namespace
}  // namespace granular
