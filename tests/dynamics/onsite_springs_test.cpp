// On-site springs in the dynamics (the quasiperiodic chain S1, docs/physics.md, "Quasiperiodic
// chains"): the splitting stepper against the Odeint reference, a small-amplitude mode against its
// linear frequency from the spectrum (an independent eigensolver), the energy ½ k u² in the
// Hamiltonian (conserved to the scheme's τ⁴ error), and the tangent map against two nearby orbits.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics_fixtures.hpp"
#include "granular/dynamics/damping.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/error.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/quasiperiodic.hpp"

namespace granular {
namespace {

using fixtures::relative_difference;

// S1 at λ = 0.7 (above the transition λ k0 = 2K at k0 = 4K: localized modes), N beads, F0 = 10 N.
Chain onsite_springs_chain(std::size_t n, double lambda = 0.7) {
  const Quasiperiodic q{.kind = Quasiperiodic::Kind::s1, .modulation = lambda, .phase = 0.4};
  return quasiperiodic_chain(q, n, fixtures::r1, 10.0, steel, 0.4);
}

// The same beads and bonds without the springs: what a dropped on-site term would integrate.
Chain onsite_springs_removed(Chain c) {
  c.onsite.clear();
  return c;
}

TEST(OnsiteSprings, Saba2cAgreesWithTheReferenceIntegrator) {
  const Chain chain = onsite_springs_chain(101);
  for (ForceLawKind kind : {ForceLawKind::hertz, ForceLawKind::linear}) {
    const ForceLaw law = make_force_law(kind, chain);
    ASSERT_TRUE(grounded(law));
    const State s0 = velocity_kick(chain, 50, matched_velocity(law, chain, 50, 1e-7));
    const double tau = 0.02e-6, duration = 0.5e-3;
    const auto ref = fixtures::run(make_reference_propagator(law, chain, tau, s0, {1e-16, 1e-16, 0}),
                                   fixtures::steps_for(duration, tau));
    const auto p =
        fixtures::run(make_splitting_propagator(law, chain, saba2c(), tau, s0), fixtures::steps_for(duration, tau));
    const auto bare = fixtures::run(make_splitting_propagator(make_force_law(kind, onsite_springs_removed(chain)),
                                                              chain, saba2c(), tau, s0),
                                    fixtures::steps_for(duration, tau));
    const double error = relative_difference(p->displacement(), ref->displacement());
    const double without = relative_difference(bare->displacement(), ref->displacement());
    std::printf("  %s: SABA2C vs reference %.3e; without the springs %.3e\n", to_string(kind).c_str(), error, without);
    EXPECT_LT(error, 1e-9);
    EXPECT_GT(without, 1e-2);  // the springs matter: the comparison can fail
  }
}

// A mode of the linearized S1 chain, v = M^{-1/2} w, started at rest with a 1e-11 m amplitude, must
// stay v cos(ωt) with ω² the eigenvalue of the dynamical matrix (which holds k_n/m_n on its
// diagonal). The linear law isolates the on-site term; Hertz at 1e-11 m (the static overlap is ~1e-6 m) is linear to ~1e-5.
TEST(OnsiteSprings, SmallAmplitudeModeOscillatesAtItsLinearFrequency) {
  const Chain chain = onsite_springs_chain(89);
  const Spectrum s = spectrum(dynamical_matrix(chain), all_modes(), {.vectors = true});
  for (std::size_t j : {std::size_t{0}, std::size_t{44}, std::size_t{88}}) {
    const double omega = std::sqrt(s.omega2[j]);
    State s0(chain.size());
    double largest = 0;
    for (std::size_t i = 0; i < chain.size(); ++i)
      largest = std::max(largest, std::abs(s.vector(j)[i] / std::sqrt(chain.mass[i])));
    for (std::size_t i = 0; i < chain.size(); ++i)
      s0.u[i] = 1e-11 * s.vector(j)[i] / std::sqrt(chain.mass[i]) / largest;
    for (ForceLawKind kind : {ForceLawKind::linear, ForceLawKind::hertz}) {
      const ForceLaw law = make_force_law(kind, chain);
      const double period = 2 * std::numbers::pi / omega, tau = period / 400;
      auto p = make_splitting_propagator(law, chain, saba2c(), tau, s0, {.enabled = false});
      double worst = 0;
      for (int quarter = 1; quarter <= 12; ++quarter) {  // three periods, every quarter: cos = 0, ±1
        p->advance(100);
        std::vector<double> expected(chain.size());
        const double c = std::cos(omega * p->time());
        for (std::size_t i = 0; i < chain.size(); ++i) expected[i] = s0.u[i] * c;
        double d = 0, norm = 0;
        for (std::size_t i = 0; i < chain.size(); ++i) {
          d += (p->displacement()[i] - expected[i]) * (p->displacement()[i] - expected[i]);
          norm += s0.u[i] * s0.u[i];
        }
        worst = std::max(worst, std::sqrt(d / norm));
      }
      std::printf("  mode %zu (f = %.3f kHz) %s: |u(t) - u0 cos wt| / |u0| <= %.2e\n", j + 1, s.freq_khz[j],
                  to_string(kind).c_str(), worst);
      EXPECT_LT(worst, kind == ForceLawKind::linear ? 1e-8 : 1e-5);  // measured 5e-10, 1e-6
    }
  }
}

// Relative energy error of a kicked S1 chain, max over `samples` times.
double onsite_springs_energy_error(const Chain& chain, double tau, double duration, std::size_t samples,
                                   std::size_t begin = 0) {
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const State s0 = velocity_kick(chain, chain.size() / 2, matched_velocity(law, chain, chain.size() / 2, 1e-7));
  const double h0 = total_energy(law, chain, s0);
  auto p = make_splitting_propagator(law, chain, saba2c(), tau, s0);
  const std::size_t steps = fixtures::steps_for(duration, tau);
  double worst = 0;
  for (std::size_t k = 1; k <= samples; ++k) {
    p->advance(steps * k / samples - p->steps_done());
    if (k > begin) worst = std::max(worst, std::abs(total_energy(law, chain, p->state()) - h0) / h0);
  }
  return worst;
}

TEST(OnsiteSprings, EnergyWithTheSpringsIsConservedAndFallsAsTauToTheFourth) {
  const Chain chain = onsite_springs_chain(201);
  const double coarse = onsite_springs_energy_error(chain, 0.5e-6, 5e-3, 100);
  const double fine = onsite_springs_energy_error(chain, 0.25e-6, 5e-3, 100);
  const double first = onsite_springs_energy_error(chain, 0.5e-6, 2.5e-3, 50);
  const double second = onsite_springs_energy_error(chain, 0.5e-6, 5e-3, 100, 50);
  // Leaving ½ k u² out of H (or −k u out of the force) makes H swing by O(1) of itself.
  const ForceLaw bare = make_force_law(ForceLawKind::hertz, onsite_springs_removed(chain));
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const State s0 = displacement_kick(chain, 100, 1e-7);
  const double share = 1 - total_energy(bare, chain, s0) / total_energy(law, chain, s0);
  std::printf(
      "  max |H - H0|/H0: %.3e at 0.5 us, %.3e at 0.25 us (ratio %.1f); halves %.3e %.3e; spring share "
      "of a displacement kick's energy %.3f\n",
      coarse, fine, coarse / fine, first, second, share);
  EXPECT_LT(coarse, 1e-7);         // measured 3.5e-8
  EXPECT_GE(coarse / fine, 12.0);  // τ⁴: 16
  EXPECT_LE(second, 1.5 * first);  // no drift
  EXPECT_GT(share, 0.1);           // the springs hold a sizeable part of the energy
}

TEST(OnsiteSprings, TangentMapIsTheDifferenceOfTwoNearbyOrbits) {
  const Chain chain = onsite_springs_chain(51);
  const double alpha = 1e-7, epsilon = 1e-9;
  for (ForceLawKind kind : {ForceLawKind::hertz, ForceLawKind::fpu}) {
    const ForceLaw law = make_force_law(kind, chain);
    const State a = displacement_kick(chain, 25, alpha);
    State w(chain.size());
    for (std::size_t i = 0; i < chain.size(); ++i) {
      w.u[i] = alpha * std::sin(1.1 * static_cast<double>(i) + 0.3);
      w.v[i] = alpha / 1e-6 * 0.2 * std::cos(0.9 * static_cast<double>(i));
    }
    State b = a;
    for (std::size_t i = 0; i < a.size(); ++i) {
      b.u[i] += epsilon * w.u[i];
      b.v[i] += epsilon * w.v[i];
    }
    const double tau = 0.5e-6;
    const std::size_t steps = 200;
    auto tangent = make_tangent_propagator(law, chain, saba2c(), tau, a, w, {.enabled = true, .renormalize_every = 0});
    tangent->advance(steps);
    auto pa = fixtures::run(make_splitting_propagator(law, chain, saba2c(), tau, a, {.enabled = false}), steps);
    auto pb = fixtures::run(make_splitting_propagator(law, chain, saba2c(), tau, b, {.enabled = false}), steps);
    EXPECT_EQ(relative_difference(tangent->displacement(), pa->displacement()), 0.0);  // the stepper's orbit
    const auto fd = fixtures::finite_difference_deviation(*pa, *pb, epsilon);
    const double eu = relative_difference(tangent->deviation_displacement(), fd.u);
    const double ev = relative_difference(tangent->deviation_velocity(), fd.v);
    std::printf("  %s: |dev - finite difference| / |dev|: u %.2e, v %.2e\n", to_string(kind).c_str(), eu, ev);
    EXPECT_LT(eu, 1e-5);
    EXPECT_LT(ev, 1e-5);
  }
}

// Damped S1 (viscous on-site damping and Kuwabara–Kono contact damping with the springs): the
// linear chain against its exact damped modes (the springs in the modes), and the energy balance
// H + dissipated = H0 of the Hertz chain while contacts open (the springs' energy in H).
TEST(OnsiteSprings, DampedLinearChainDecaysAsItsExactDampedModes) {
  const Chain chain = onsite_springs_chain(41);
  const ForceLaw law = make_force_law(ForceLawKind::linear, chain);
  const State s0 = displacement_kick(chain, 20, 1e-7);
  const double tau_d = 0.1e-3, duration = 0.3e-3;
  const std::vector<double> exact = fixtures::damped_modal_solution(chain, s0, duration, tau_d);
  // The springs matter to the answer: the same damped run without them is far off.
  const auto without =
      fixtures::run(make_damped_propagator(make_force_law(ForceLawKind::linear, onsite_springs_removed(chain)),
                                           onsite_springs_removed(chain), saba2c(), 0.04e-6, s0, {tau_d, 0}),
                    fixtures::steps_for(duration, 0.04e-6));
  EXPECT_GT(relative_difference(without->displacement(), exact), 0.5);
  fixtures::expect_second_order_to_exact_damped_modes(law, chain, s0, tau_d, duration, {0.04e-6, 0.02e-6}, exact);
}

TEST(OnsiteSprings, DampedEnergyBalanceClosesWithTheSprings) {
  const Quasiperiodic q{.kind = Quasiperiodic::Kind::s1, .modulation = 0.7, .phase = 0.4};
  const Chain chain = quasiperiodic_chain(q, 101, fixtures::r1, 0.1, steel, 0.4);  // F0 = 0.1 N: contacts open
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const State s0 = velocity_kick(chain, 50, 8e-3);
  for (const Damping damping : {Damping{0.3e-3, 0}, Damping{1e-3, 5e-6}}) {
    const auto balance = fixtures::damped_energy_balance(law, chain, s0, damping, 5);
    EXPECT_GT(balance.lost, 0.1);
    EXPECT_LT(balance.worst, 1e-7);
  }
}

}  // namespace
}  // namespace granular
