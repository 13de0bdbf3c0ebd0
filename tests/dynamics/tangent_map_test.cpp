// The tangent map (docs/beyond-the-paper.md): the deviation vector is the derivative
// of the numerical orbit (two orbits 1e-9 apart), and the linear chain is regular (X1 ∝ ln t / t).
#include <cmath>
#include <cstdio>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics_fixtures.hpp"
#include "granular/dynamics/damping.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

using fixtures::relative_difference;

// A deviation over the whole chain with the scales of the state: α in u, α/1 µs in v.
State spread_deviation(std::size_t n, double alpha) {
  State w(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i);
    w.u[i] = alpha * std::sin(1.3 * x + 0.2);
    w.v[i] = alpha / 1e-6 * 0.3 * std::cos(0.7 * x);
  }
  return w;
}

TEST(TangentMap, DeviationIsTheDifferenceOfTwoNearbyOrbits) {
  const double alpha = 1e-7, epsilon = 1e-9;
  for (ForceLawKind kind : {ForceLawKind::hertz, ForceLawKind::fpu})
    for (const SplittingScheme& scheme : {saba2c(), aba864()}) {
      const Chain chain = fixtures::anderson(51, 1.0);  // ε ≈ 0.36: strongly nonlinear, contacts closed
      const ForceLaw law = make_force_law(kind, chain);
      const State a = displacement_kick(chain, 25, alpha);
      const State w = spread_deviation(chain.size(), alpha);
      State b = a;
      for (std::size_t i = 0; i < a.size(); ++i) {
        b.u[i] += epsilon * w.u[i];
        b.v[i] += epsilon * w.v[i];
      }
      const double tau = 0.5e-6;
      const std::size_t steps = 200;  // 0.1 ms: the pulse crosses ~10 beads, many oscillations
      auto tangent = make_tangent_propagator(law, chain, scheme, tau, a, w, {.enabled = true, .renormalize_every = 0});
      tangent->advance(steps);
      // The orbits through the damped stepper with no damping (the conservative stepper, whole chain).
      auto pa = fixtures::run(make_damped_propagator(law, chain, scheme, tau, a, {}), steps);
      auto pb = fixtures::run(make_damped_propagator(law, chain, scheme, tau, b, {}), steps);
      EXPECT_EQ(relative_difference(tangent->displacement(), pa->displacement()), 0.0);  // same orbit
      const auto fd = fixtures::finite_difference_deviation(*pa, *pb, epsilon);
      const double eu = relative_difference(tangent->deviation_displacement(), fd.u);
      const double ev = relative_difference(tangent->deviation_velocity(), fd.v);
      // How far w has moved from its start: the comparison is not trivial.
      const double moved = relative_difference(tangent->deviation_displacement(), w.u);
      std::printf("  %s %s: |dev - finite difference| / |dev|: u %.2e, v %.2e (moved %.2f)\n", to_string(kind).c_str(),
                  scheme.name.c_str(), eu, ev, moved);
      EXPECT_LT(eu, 1e-5);
      EXPECT_LT(ev, 1e-5);
      EXPECT_GT(moved, 0.1);
    }
}

TEST(TangentMap, LinearChainIsRegularX1FallsAsLogTOverT) {
  const Chain chain = fixtures::anderson(201, 10.0);
  const ForceLaw law = make_force_law(ForceLawKind::linear, chain);
  const State s0 = displacement_kick(chain, 100, 1e-7);
  const double tau = 1e-6;
  auto p = make_tangent_propagator(law, chain, saba2c(), tau, s0, localized_deviation(chain.size(), 100));
  double worst = 0, x1_1ms = 0;
  for (std::size_t step = 100; step <= 10000; step += 100) {
    p->advance(step - p->steps_done());
    const double t = p->time(), x1 = p->mle();
    worst = std::max(worst, std::abs(x1) * t / std::log(t / tau));
    if (step == 1000) x1_1ms = x1;
  }
  std::printf("  X1(1 ms) = %.3e /s, X1(10 ms) = %.3e /s, max |X1| t / ln(t/tau) = %.3f\n", x1_1ms, p->mle(), worst);
  EXPECT_LT(worst, 1.0);
  EXPECT_LT(std::abs(p->mle()), std::abs(x1_1ms) / 4);  // ~1/t: ten times later, several times smaller
}

// ‖(δu, δv)‖ in the tangent map's norm (t_unit = 1 µs).
double deviation_norm(std::span<const double> du, std::span<const double> dv) {
  double s = 0;
  for (std::size_t i = 0; i < du.size(); ++i) s += du[i] * du[i] + (1e-6 * dv[i]) * (1e-6 * dv[i]);
  return std::sqrt(s);
}

// A chaotic Hertz orbit: 8 beads in the sonic vacuum (F0 = 0, so contacts open and close), each bead
// given a velocity. X1 of the tangent map settles to a positive value (its halves agree), far above
// the regular ln t / t, and it equals the growth rate of the distance of two orbits 1e-8 apart
// (Benettin's two-orbit method: the second orbit pulled back to that distance every 20 µs).
TEST(TangentMap, ChaoticOrbitHasAPositiveX1EqualToTheTwoOrbitDivergence) {
  const Chain chain = fixtures::anderson(8, 0.0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  State a(chain.size());
  for (std::size_t i = 0; i < a.size(); ++i) a.v[i] = 1e-2 * std::sin(2.1 * static_cast<double>(i) + 0.4);
  const double tau = 0.2e-6;
  const std::size_t interval = 100, intervals = 2500;  // 20 µs, 50 ms in all
  const State w = spread_deviation(chain.size(), 1e-9);
  auto tangent = make_tangent_propagator(law, chain, saba2c(), tau, a, w, {.enabled = true, .renormalize_every = 10});
  // The two orbits, each interval restarted from a and from a + d0 · (b − a)/|b − a|.
  const double d0 = 1e-8 * deviation_norm(a.u, a.v) + 1e-17;
  State b = a;
  {
    const double n0 = deviation_norm(w.u, w.v);
    for (std::size_t i = 0; i < a.size(); ++i) {
      b.u[i] += d0 * w.u[i] / n0;
      b.v[i] += d0 * w.v[i] / n0;
    }
  }
  double stretch = 0, x1_half = 0, two_orbit_half = 0;
  for (std::size_t k = 1; k <= intervals; ++k) {
    tangent->advance(interval);
    auto pa = fixtures::run(make_damped_propagator(law, chain, saba2c(), tau, a, {}), interval);
    auto pb = fixtures::run(make_damped_propagator(law, chain, saba2c(), tau, b, {}), interval);
    std::vector<double> du(a.size()), dv(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      a.u[i] = pa->displacement()[i], a.v[i] = pa->velocity()[i];
      du[i] = pb->displacement()[i] - a.u[i], dv[i] = pb->velocity()[i] - a.v[i];
    }
    const double d = deviation_norm(du, dv);
    stretch += std::log(d / d0);
    for (std::size_t i = 0; i < a.size(); ++i) b.u[i] = a.u[i] + du[i] * d0 / d, b.v[i] = a.v[i] + dv[i] * d0 / d;
    if (k == intervals / 2) x1_half = tangent->mle(), two_orbit_half = stretch / tangent->time();
  }
  EXPECT_EQ(relative_difference(tangent->displacement(), a.u), 0.0);  // the same orbit
  const double x1 = tangent->mle(), two_orbit = stretch / tangent->time();
  const double t = tangent->time();
  std::printf("  X1(25 ms) = %.4e /s, X1(50 ms) = %.4e /s; two orbits: %.4e, %.4e /s; X1 t / ln(t/tau) = %.1f\n",
              x1_half, x1, two_orbit_half, two_orbit, x1 * t / std::log(t / tau));
  EXPECT_GT(x1, 0);
  EXPECT_NEAR(x1, x1_half, 0.1 * x1);         // converged
  EXPECT_NEAR(two_orbit, x1, 0.05 * x1);      // the same exponent by two methods
  EXPECT_GT(x1 * t / std::log(t / tau), 10);  // regular motion stays below 1 (LinearChainIsRegular...)
}

TEST(TangentMap, RenormalizationDoesNotChangeTheExponent) {
  const Chain chain = fixtures::anderson(101, 0.1);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const State s0 = velocity_kick(chain, 50, 8e-3);
  const State w = localized_deviation(chain.size(), 50);
  auto raw = make_tangent_propagator(law, chain, saba2(), 0.2e-6, s0, w, {.enabled = true, .renormalize_every = 0});
  auto renormalized =
      make_tangent_propagator(law, chain, saba2(), 0.2e-6, s0, w, {.enabled = true, .renormalize_every = 7});
  raw->advance(5000);
  renormalized->advance(5000);
  std::printf("  X1(1 ms) = %.6e /s raw, %.6e /s renormalized\n", raw->mle(), renormalized->mle());
  EXPECT_NEAR(raw->mle(), renormalized->mle(), 1e-9 * std::abs(raw->mle()));
  const auto share = renormalized->deviation_distribution();
  double total = 0;
  for (double x : share) total += x;
  EXPECT_NEAR(total, 1.0, 1e-12);
}

TEST(TangentMap, RejectsAZeroDeviation) {
  const Chain chain = fixtures::anderson(11, 1.0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  EXPECT_THROW(make_tangent_propagator(law, chain, saba2c(), 1e-6, displacement_kick(chain, 5, 1e-7), State(11)),
               InvalidInput);
}

}  // namespace
}  // namespace granular
