// The time-step rule: the scheme's stability constant against the leapfrog's known 2 and against
// the stepper itself (just below it a mode stays bounded, just above it blows up); the frequency
// bound against the exact spectrum; the paper's defaults keep τ = 1 µs, small ξ does not.
#include "granular/case/time_step_rule.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include "granular/case/mode_kick.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/disorder.hpp"
#include "granular/model/material.hpp"
#include "granular/study/exponent_table.hpp"

namespace granular {
namespace {

TEST(TimeStepRule, LeapfrogIsStableUpToTwo) {
  const SplittingScheme leapfrog{"leapfrog", {0.5, 0.5}, {1}, 0, 2};
  EXPECT_NEAR(stable_step_limit(leapfrog), 2.0, 1e-9);
}

// Two leapfrog steps of nearly equal length x h and (1 − x) h: a parametric-resonance gap of width
// ≈ 5.7 (1/2 − x) around h = 2√2 (|trace| > 2 there), far narrower than a scan in steps of 1e-3
// could see (x = 0.49995: ~3e-4 wide, between the scan's points 2.828 and 2.829); the next
// instability is at h ≈ 4. h* must stop at the gap.
TEST(TimeStepRule, ANarrowUnstableGapIsNotSteppedOver) {
  const double x = 0.49995;
  const SplittingScheme two{"two-leapfrogs", {x / 2, 0.5, (1 - x) / 2}, {x, 1 - x}, 0, 2};
  const double h = stable_step_limit(two);
  EXPECT_NEAR(h, 2 * std::sqrt(2.0), 5e-4);
  EXPECT_GT(std::fabs(step_trace(two, h * (1 + 1e-9))), 2);
  for (double y = 1e-4; y < h; y += 1e-4) ASSERT_LE(std::fabs(step_trace(two, y)), 2) << y;
}

// Two equal beads between spherical walls of the same bond, linear law: ω² ∈ {k/m, 3k/m}; the
// fast mode is (1, −1)/√2.
Chain two_beads() {
  ChainSpec spec;
  spec.radii = {4.76e-3, 4.76e-3};
  spec.materials = {steel};
  spec.left_wall.radius = spec.right_wall.radius = 4.76e-3;
  spec.precompression = 10;
  return make_chain(spec);
}

// The stepper itself, one step on the fast mode from (x, v/ω) = (1, 0) and (0, 1): the trace of
// the map it applies equals the formula's, for every scheme, at several h.
TEST(TimeStepRule, TheTraceIsTheSteppersOwn) {
  const Chain chain = two_beads();
  const ForceLaw law = make_force_law(ForceLawKind::linear, chain);
  const double omega = std::sqrt(3 * linear_stiffness(chain)[1] / chain.mass[0]);
  const double a = 1e-9 / std::sqrt(2.0);
  for (const auto& scheme : {saba2c(), saba2(), aba864(), srkn14a()})
    for (double h : {0.3, 1.0, 2.0, 2.7}) {
      double trace = 0;
      for (int column = 0; column < 2; ++column) {
        State s(2);
        if (column == 0) s.u = {a, -a};
        else s.v = {a * omega, -a * omega};
        auto p = make_splitting_propagator(law, chain, scheme, h / omega, s, ActiveWindow{false});
        p->advance(1);
        const State after = p->state();
        const double x = (after.u[0] - after.u[1]) / (2 * a), y = (after.v[0] - after.v[1]) / (2 * a * omega);
        trace += column == 0 ? x : y;
      }
      EXPECT_NEAR(trace, step_trace(scheme, h), 1e-9) << scheme.name << " h " << h;
    }
}

// h*: stable on all of (0, h*], unstable just past it; and on SABA2C, the stepper blows up 2 % past it.
TEST(TimeStepRule, TheLimitIsTheFirstInstability) {
  for (const auto& scheme : {saba2c(), saba2(), aba864(), srkn14a()}) {
    const double h = stable_step_limit(scheme);
    EXPECT_GT(h, 0.5) << scheme.name;
    for (double x = 1e-3; x < h; x += 1e-3) ASSERT_LE(std::fabs(step_trace(scheme, x)), 2) << scheme.name << " " << x;
    EXPECT_GT(std::fabs(step_trace(scheme, h * (1 + 1e-9))), 2) << scheme.name;
  }
  const Chain chain = two_beads();
  const ForceLaw law = make_force_law(ForceLawKind::linear, chain);
  const double omega = std::sqrt(3 * linear_stiffness(chain)[1] / chain.mass[0]);
  State fast(2);
  fast.u = {1e-9, -1e-9};
  const double energy0 = total_energy(law, chain, fast), h = stable_step_limit(saba2c());
  for (const auto& [factor, stable] : {std::pair{0.98, true}, std::pair{1.02, false}}) {
    auto p = make_splitting_propagator(law, chain, saba2c(), factor * h / omega, fast, ActiveWindow{false});
    p->advance(20000);
    const double growth = total_energy(law, chain, p->state()) / energy0;
    EXPECT_EQ(growth < 10, stable) << factor << " h*: energy grew " << growth << "-fold";
  }
}

TEST(TimeStepRule, FrequencyBoundHoldsAndIsNotFarAbove) {
  for (double xi : {0.1, 0.5, 1.0}) {
    const Chain chain =
        make_chain(radii_of(realization_configuration(Disorder::anderson, 0.5, 200, 1, 0), 4.76e-3, xi), 10.0);
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
    EXPECT_EQ(default_time_step(limit), 1e-6) << to_string(c.chain.draw().disorder) << " F0 " << c.chain.F0;
    EXPECT_GT(limit.max_time_step, default_step_margin * 1e-6);
  }
  TransportCase small;
  small.chain.draw().xi = 0.05;
  const TimeStepLimit limit = time_step_limit(small);
  EXPECT_LT(limit.max_time_step, 1e-6);
  const double tau = default_time_step(limit), bound = limit.max_time_step / default_step_margin;
  EXPECT_LE(tau, bound);
  EXPECT_GT(tau * (1 + 1e-12), 1e-6 / std::ceil(1e-6 / bound));
  EXPECT_NEAR(1e-6 / tau, std::round(1e-6 / tau), 1e-9);
  small.dynamics.integration.time_step = 1e-6;
  EXPECT_THROW(check_time_step(small, limit), InvalidInput);
}

// Chains from a bead distribution are bounded by their own radii: two types of the paper's radii
// give the paper's limit to the bit; a third, smaller type raises ω_max; a polydisperse range is
// bounded at least as tightly as its two ends alone (and not absurdly more).
TEST(TimeStepRule, BeadDistributionsBoundTheirOwnRadii) {
  for (Kick kick : {Kick::displacement, Kick::velocity}) {
    TransportCase paper;
    paper.chain.draw().q = 0.3;
    paper.kick = kick;
    TransportCase two = paper;
    two.chain.source = BeadDistribution{.radii = {4.76e-3, 2.38e-3}, .probabilities = {0.3, 0.7}};
    EXPECT_EQ(time_step_limit(two).omega_max, time_step_limit(paper).omega_max);
    TransportCase three = two;
    three.chain.source = BeadDistribution{.radii = {4.76e-3, 2.38e-3, 1e-3}, .probabilities = {0.3, 0.6, 0.1}};
    EXPECT_GT(time_step_limit(three).omega_max, 1.2 * time_step_limit(paper).omega_max);
    TransportCase poly = paper;
    poly.chain.source = BeadDistribution{.kind = BeadDistribution::Kind::uniform, .low = 1e-3, .high = 4.76e-3};
    TransportCase ends = paper;  // the range's two ends: among the 9 radii the rule takes
    ends.chain.source = BeadDistribution{.radii = {4.76e-3, 1e-3}, .probabilities = {0.5, 0.5}};
    EXPECT_GE(time_step_limit(poly).omega_max, time_step_limit(ends).omega_max);
    EXPECT_LT(time_step_limit(poly).omega_max, 1.5 * time_step_limit(ends).omega_max);
  }
}

// A mode kick of a chain not yet drawn: any mode number of an N-bead chain is accepted (the probe
// chains have three beads), the energy bound is the given energy, and from an amplitude α it is
// at least the energy of the mode at α on a real realization.
TEST(TimeStepRule, ModeKicksAreBoundedBeforeTheChainIsDrawn) {
  TransportCase c;
  c.chain.N = 401;
  c.site = 201;
  c.kick = Kick::mode;
  c.mode = {.mode = 200, .energy = 1e-7};
  validate(c);
  const TimeStepLimit given = time_step_limit(c);
  TransportCase site = c;  // a velocity kick of the same energy on the same probe chains
  site.kick = Kick::velocity;
  site.beta = std::sqrt(2 * 1e-7 / sphere_mass(steel, 4.76e-3));  // ½mβ² = E on the heaviest bead
  EXPECT_NEAR(given.omega_max, time_step_limit(site).omega_max, 1e-9 * given.omega_max);
  c.mode = {.mode = 200};
  c.alpha = 1e-7;
  const TimeStepLimit from_alpha = time_step_limit(c);
  EXPECT_GT(from_alpha.omega_max, 0);
  const Chain chain = make_chain(radii_of(realization_configuration(Disorder::anderson, 0.5, c.chain.N, c.chain.seed, 0),
                                          c.chain.R1, c.chain.xi()),
                                 c.chain.F0);
  const ModeKickResult real = mode_kick(chain, ForceLawKind::hertz, {.mode = 200, .amplitude = 1e-7});
  const double bound_at_real = highest_frequency_bound(make_force_law(ForceLawKind::hertz, chain), chain, real.energy);
  EXPECT_GE(from_alpha.omega_max, bound_at_real);
  EXPECT_NO_THROW(settle_time_step(c));
}

}  // namespace
}  // namespace granular
