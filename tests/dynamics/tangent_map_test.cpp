// The tangent map (SPEC §4 "Beyond the paper", issue 14): the deviation vector is the derivative
// of the numerical orbit (two orbits 1e-9 apart), and the linear chain is regular (X1 ∝ ln t / t).
#include <cmath>
#include <cstdio>

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
      std::vector<double> du(a.size()), dv(a.size());
      for (std::size_t i = 0; i < a.size(); ++i) {
        du[i] = (pb->displacement()[i] - pa->displacement()[i]) / epsilon;
        dv[i] = (pb->velocity()[i] - pa->velocity()[i]) / epsilon;
      }
      const double eu = relative_difference(tangent->deviation_displacement(), du);
      const double ev = relative_difference(tangent->deviation_velocity(), dv);
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
