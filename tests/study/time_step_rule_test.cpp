// The time-step rule: the scheme's stability constant against the leapfrog's known 2 and against
// the stepper itself (just below it a mode stays bounded, just above it blows up); the frequency
// bound against the exact spectrum; the paper's defaults keep τ = 1 µs, small ξ does not.
#include "granular/study/time_step_rule.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/disorder.hpp"
#include "granular/study/exponent_table.hpp"

namespace granular {
namespace {

TEST(TimeStepRule, LeapfrogIsStableUpToTwo) {
  const SplittingScheme leapfrog{"leapfrog", {0.5, 0.5}, {1}, 0, 2};
  EXPECT_NEAR(stable_step_limit(leapfrog), 2.0, 1e-9);
}

// Two equal beads between spherical walls of the same bond, linear law: ω² ∈ {k/m, 3k/m}.
// The stepper itself, on the fast mode, just inside and just outside h*/ω.
TEST(TimeStepRule, EverySchemeIsStableJustBelowItsLimitAndNotAbove) {
  ChainSpec spec;
  spec.radii = {4.76e-3, 4.76e-3};
  spec.materials = {steel};
  spec.left_wall.radius = spec.right_wall.radius = 4.76e-3;
  spec.precompression = 10;
  const Chain chain = make_chain(spec);
  const ForceLaw law = make_force_law(ForceLawKind::linear, chain);
  const double k = linear_stiffness(chain)[1];
  const double omega = std::sqrt(3 * k / chain.mass[0]);
  State fast(2);
  fast.u = {1e-9, -1e-9};
  for (const auto& scheme : {saba2c(), saba2(), aba864(), srkn14a()}) {
    const double h = stable_step_limit(scheme);
    EXPECT_GT(h, 0.5) << scheme.name;
    const double energy0 = total_energy(law, chain, fast);
    for (const auto& [factor, stable] : {std::pair{0.98, true}, std::pair{1.02, false}}) {
      auto p = make_splitting_propagator(law, chain, scheme, factor * h / omega, fast, ActiveWindow{false});
      p->advance(20000);
      const double growth = total_energy(law, chain, p->state()) / energy0;
      if (stable) EXPECT_LT(growth, 10) << scheme.name << " at " << factor << " h*";
      else EXPECT_GT(growth, 1e3) << scheme.name << " at " << factor << " h*";
    }
  }
}

TEST(TimeStepRule, FrequencyBoundHoldsAndIsNotFarAbove) {
  for (double xi : {0.1, 0.5, 1.0}) {
    const Chain chain = make_chain(radii_of(realization_configuration(Disorder::anderson, 0.5, 200, 1, 0), 4.76e-3, xi),
                                   10.0);
    const double exact = std::sqrt(spectrum(dynamical_matrix(chain)).omega2.back());
    const double bound = highest_frequency_bound(make_force_law(ForceLawKind::hertz, chain), chain, 1e-15);
    EXPECT_GE(bound, exact) << "xi " << xi;
    EXPECT_LT(bound, 1.5 * exact) << "xi " << xi;
  }
}

TEST(TimeStepRule, ThePapersCasesKeepOneMicrosecondSmallXiDoesNot) {
  const ExponentTableConfig paper;  // h, A, RDM1, RDM2 × F0 10 … 0 × both kicks, ξ = q = 0.5
  for (const TransportCase& c : exponent_cases(paper)) {
    const TimeStepLimit limit = time_step_limit(c);
    EXPECT_EQ(default_time_step(limit), 1e-6) << to_string(c.disorder) << " F0 " << c.precompression;
    EXPECT_GT(limit.max_time_step, default_step_margin * 1e-6);
  }
  TransportCase small;
  small.xi = 0.05;
  const TimeStepLimit limit = time_step_limit(small);
  EXPECT_LT(limit.max_time_step, 1e-6);
  const double tau = default_time_step(limit), bound = limit.max_time_step / default_step_margin;
  EXPECT_LE(tau, bound);
  EXPECT_GT(tau * (1 + 1e-12), 1e-6 / std::ceil(1e-6 / bound));
  EXPECT_NEAR(1e-6 / tau, std::round(1e-6 / tau), 1e-9);
  small.dynamics.time_step = 1e-6;
  EXPECT_THROW(check_time_step(small, limit), InvalidInput);
}

}  // namespace
}  // namespace granular
