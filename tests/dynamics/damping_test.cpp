// Dissipation (docs/beyond-the-paper.md): the damped linear chain against its exact
// modal solution, the order of the Strang splitting with Kuwabara–Kono damping, the energy
// balance H + dissipated = H0, and "no damping" changing nothing.
#include <cmath>
#include <cstdio>
#include <utility>

#include <gtest/gtest.h>

#include "dynamics_fixtures.hpp"
#include "granular/dynamics/damping.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/observers.hpp"
#include "granular/dynamics/spread.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

using fixtures::relative_difference;

using fixtures::steps_for;

TEST(Damping, LinearChainDecaysEveryModeAsTheExactDampedOscillator) {
  const Chain chain = fixtures::anderson(41, 10.0);
  const ForceLaw law = make_force_law(ForceLawKind::linear, chain);
  const State s0 = displacement_kick(chain, 20, 1e-7);
  const double tau_d = 0.1e-3, duration = 0.3e-3;  // the amplitude falls by e^{-1.5}
  const std::vector<double> exact = fixtures::damped_modal_solution(chain, s0, duration, tau_d);
  // Undamped, the same state would be far off: the test sees the decay.
  const auto free = fixtures::run(make_splitting_propagator(law, chain, saba2c(), 0.01e-6, s0, {false}),
                                  steps_for(duration, 0.01e-6));
  EXPECT_GT(relative_difference(free->displacement(), exact), 0.5);
  fixtures::expect_second_order_to_exact_damped_modes(law, chain, s0, tau_d, duration, {0.04e-6, 0.02e-6, 0.01e-6},
                                                      exact);
}

TEST(Damping, KuwabaraKonoSplittingIsSecondOrder) {
  // F0 = 10 N and a small kick: contacts stay closed, the force is smooth.
  const Chain chain = fixtures::anderson(51, 10.0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const State s0 = displacement_kick(chain, 25, 1e-7);
  const Damping damping{0.5e-3, 2e-6};
  const double duration = 0.2e-3;
  const auto at = [&](double tau) {
    return fixtures::run(make_damped_propagator(law, chain, saba2c(), tau, s0, damping), steps_for(duration, tau))
        ->state();
  };
  State coarse = at(0.2e-6);
  const double dissipated = [&] {
    auto p = fixtures::run(make_damped_propagator(law, chain, saba2c(), 0.1e-6, s0, damping), 2000);
    return p->dissipated_energy() / total_energy(law, chain, s0);
  }();
  std::printf("  dissipated fraction of H0 by %g ms: %.3f\n", duration * 1e3, dissipated);
  EXPECT_GT(dissipated, 0.3);  // the damping matters at this γ
  double previous = 0;
  for (double tau : {0.1e-6, 0.05e-6, 0.025e-6}) {
    const State fine = at(tau);
    const double error = relative_difference(coarse.u, fine.u);  // ≈ error of the coarser run
    std::printf("  tau = %g us: |u(tau) - u(tau/2)| / |u| = %.3e\n", 2 * tau * 1e6, error);
    if (previous > 0) {
      EXPECT_GT(previous / error, 3.2) << "tau = " << tau;
      EXPECT_LT(previous / error, 4.8) << "tau = " << tau;
    }
    previous = error;
    coarse = fine;
  }
}

TEST(Damping, EnergyBalanceClosesWhileContactsOpen) {
  // F0 = 0.1 N: the kick opens contacts, so the KK damping switches on and off.
  const Chain chain = fixtures::anderson(101, 0.1);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const State s0 = velocity_kick(chain, 50, 8e-3);
  for (const Damping damping : {Damping{0.3e-3, 0}, Damping{0, 5e-6}, Damping{1e-3, 5e-6}}) {
    const auto balance = fixtures::damped_energy_balance(law, chain, s0, damping, 10);
    EXPECT_GT(balance.lost, 0.2);
    EXPECT_LT(balance.worst, 1e-7);
  }
}

TEST(Damping, ZeroDampingLeavesTheVelocitiesAndTheRunUnchanged) {
  const Chain chain = fixtures::anderson(31, 0.1);
  State s = velocity_kick(chain, 15, 8e-3);
  s.u[14] = -2e-7;
  s.u[15] = 3e-7;  // some bonds open, some closed
  DampingFlow none(chain, {0, 0});
  std::vector<double> v = s.v;
  EXPECT_EQ(none.apply(s.u, v, 1e-6), 0.0);
  EXPECT_EQ(v, s.v);  // bit for bit
  // The damped stepper with no damping is the conservative scheme (unmerged, so to rounding).
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const auto a = fixtures::run(make_damped_propagator(law, chain, saba2c(), 1e-7, s, {}), 2000);
  const auto b = fixtures::run(make_splitting_propagator(law, chain, saba2c(), 1e-7, s, {false}), 2000);
  EXPECT_LT(relative_difference(a->displacement(), b->displacement()), 1e-12);
  EXPECT_EQ(a->dissipated_energy(), 0.0);
  // And a run without damping takes the conservative path: bit for bit.
  const auto run = [&](const Damping& damping) {
    EnergySpreadObserver energy;
    FinalStateObserver final_state;
    spread(chain, s, {.duration = 0.2e-3, .time_step = 1e-7, .damping = damping}, energy, final_state);
    return std::pair(energy.m2, final_state.state.u);
  };
  EXPECT_EQ(run({}), run(Damping{0, 0}));
}

TEST(Damping, SpreadingReportsTheDissipatedEnergy) {
  const Chain chain = fixtures::anderson(101, 1.0);
  const State s = displacement_kick(chain, 50, 1e-7);
  EnergySpreadObserver energy;
  const RunInfo info =
      spread(chain, s, {.duration = 1e-3, .time_step = 0.1e-6, .damping = Damping{0.5e-3, 1e-6}}, energy);
  ASSERT_EQ(energy.dissipated.size(), energy.t.size());
  EXPECT_GT(energy.dissipated.back() / info.initial_energy, 0.5);
  EXPECT_LT(energy.max_energy_error, 1e-7);  // the balance H + dissipated = H0
}

TEST(Damping, RejectsNegativeOrNonFiniteParameters) {
  EXPECT_THROW(validate(Damping{-1, 0}), InvalidInput);
  EXPECT_THROW(validate(Damping{0, -1}), InvalidInput);
  EXPECT_THROW(validate(Damping{std::nan(""), 0}), InvalidInput);
  EXPECT_THROW(validate(Damping{0, INFINITY}), InvalidInput);
  try {
    validate(Damping{0, -1});
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "kk_gamma");
  }
}

}  // namespace
}  // namespace granular
