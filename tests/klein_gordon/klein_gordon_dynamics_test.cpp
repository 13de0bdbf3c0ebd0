// The disordered Klein–Gordon chain in the dynamics (klein_gordon/klein_gordon.hpp: linear bonds 1/W, on-site
// springs ε̃_l with a quartic part 1, in every kernel): energy conserved to each scheme's order, the
// linear limit's modes at their LAPACK frequencies, the tangent map against nearby orbits and
// symplectic, the Lyapunov spectrum's ± pairs, the damped and reference steppers, and the customary
// initial conditions. Units as the model's: masses 1, time in 1/ω₀ (time_unit 1 for the norms).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/dynamics_fixtures.hpp"
#include "granular/chaos/lyapunov_spectrum.hpp"
#include "granular/dynamics/damping.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/error.hpp"
#include "granular/klein_gordon/klein_gordon.hpp"
#include "granular/linear/detail/lapack_eigensolver.hpp"

namespace granular {
namespace {

using fixtures::relative_difference;

constexpr double kg_w = 4;  // the published weak-chaos disorder strength

Chain kg_chain(std::size_t n, std::uint64_t seed = 1) { return klein_gordon({.N = n, .W = kg_w, .seed = seed}); }
ForceLaw kg_law(const Chain& chain) { return make_force_law(ForceLawKind::linear, chain); }

// max over samples every `every` of |H(t) − H(0)| / H(0) up to `duration`.
double kg_energy_error(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme, const State& s0,
                       double tau, double duration, double every) {
  const double h0 = total_energy(law, chain, s0);
  auto p = make_splitting_propagator(law, chain, scheme, tau, s0, {.enabled = false});
  const auto per = static_cast<std::size_t>(std::lround(every / tau));
  const auto samples = static_cast<std::size_t>(std::lround(duration / every));
  double worst = 0;
  for (std::size_t i = 0; i < samples; ++i) {
    p->advance(per);
    worst = std::max(worst, std::abs(total_energy(law, chain, p->state()) - h0) / h0);
  }
  return worst;
}

// A deviation over the whole chain, O(1) in u and v.
State kg_spread_deviation(std::size_t n) {
  State w(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i);
    w.u[i] = std::sin(1.3 * x + 0.2);
    w.v[i] = 0.3 * std::cos(0.7 * x);
  }
  return w;
}

TEST(KleinGordonDynamics, InitialConditionsCarryTheirEnergy) {
  const Chain chain = kg_chain(64);
  const ForceLaw law = kg_law(chain);
  const State single = site_energy_kick(chain, 31, 0.4);
  EXPECT_EQ(single.v[31], std::sqrt(0.8));  // p_l = √(2E)
  EXPECT_NEAR(total_energy(law, chain, single), 0.4, 1e-15);
  const State block = block_energy_kick(chain, 27, 10, 0.05, 5);
  int negative = 0;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const bool inside = i >= 27 && i < 37;
    EXPECT_EQ(block.u[i], 0.0);
    EXPECT_EQ(std::abs(block.v[i]), inside ? std::sqrt(0.1) : 0.0) << i;
    negative += block.v[i] < 0;
  }
  EXPECT_GT(negative, 0);  // random signs
  EXPECT_LT(negative, 10);
  EXPECT_NEAR(total_energy(law, chain, block), 10 * 0.05, 1e-15);
  // Reproducible by (seed, realization), another seed another pattern.
  EXPECT_EQ(block.v, block_energy_kick(chain, 27, 10, 0.05, 5).v);
  EXPECT_NE(block.v, block_energy_kick(chain, 27, 10, 0.05, 6).v);
  EXPECT_NE(block.v, block_energy_kick(chain, 27, 10, 0.05, 5, 1).v);
  EXPECT_THROW(block_energy_kick(chain, 60, 10, 0.05, 5), InvalidInput);  // past the end
  EXPECT_THROW(block_energy_kick(chain, 0, 10, 0.0, 5), InvalidInput);
  EXPECT_THROW(site_energy_kick(chain, 64, 0.4), InvalidInput);
  // Contacts mean nothing here: Hertz and FPU refuse the chain, naming the force law.
  for (ForceLawKind kind : {ForceLawKind::hertz, ForceLawKind::fpu}) {
    try {
      make_force_law(kind, chain);
      ADD_FAILURE() << to_string(kind) << " accepted linear springs";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.parameter(), "force_law");
    }
  }
}

// The stiffness bound the time-step rule uses: the on-site stiffness ε̃ + 3u² where the on-site energy
// ε̃ u²/2 + u⁴/4 reaches E, and no more (the rule's Gershgorin bound then covers every state of
// energy E); linear springs give k whatever E.
TEST(KleinGordonDynamics, OnsiteStiffnessBoundIsReachedAtTheEnergy) {
  const Chain chain = kg_chain(8);
  const ForceLaw law = kg_law(chain);
  const auto& l = std::get<PolynomialLaw>(law);
  for (std::size_t n = 0; n < chain.size(); ++n)
    for (double e : {1e-6, 0.4, 10.0}) {
      const double bound = l.onsite_stiffness_bound(n, e), k = chain.onsite[n];
      const double u2 = (bound - k) / 3;  // the displacement² where the bound is reached
      EXPECT_NEAR(l.onsite_potential(n, std::sqrt(u2)), e, 1e-14 * std::max(e, 1.0)) << n << " " << e;
      EXPECT_GT(bound, k);
    }
  Chain linear = chain;
  linear.onsite_quartic.clear();
  EXPECT_EQ(std::get<PolynomialLaw>(kg_law(linear)).onsite_stiffness_bound(3, 10.0), chain.onsite[3]);
}

// W = 4, one site excited with E = 0.4 (Skokos et al. 2009's single-site case), t = 100: halving τ
// divides the largest relative energy error by 2^order of each scheme. SABA2C is 4th order here
// (the corrector is exact for H = T(p) + V(x)), so its ratio is ~16; SABA2 without it is the 2nd
// order one (~4). Measured: SABA2C 1.47e-6 → 9.17e-8 (16.0), SABA2 3.64e-4 → 9.11e-5 (4.00),
// ABA864 from τ = 0.2 16.0, SRKN14a from τ = 0.2 66 (at τ = 0.4 it is not yet asymptotic: 41).
TEST(KleinGordonDynamics, EnergyErrorFallsWithEachSchemesOrder) {
  const Chain chain = kg_chain(64);
  const ForceLaw law = kg_law(chain);
  const State s0 = site_energy_kick(chain, 31, 0.4);
  struct Case {
    SplittingScheme scheme;
    double tau;
  };
  double saba2c_error = 0;
  for (const Case& c : {Case{saba2c(), 0.1}, Case{saba2(), 0.1}, Case{aba864(), 0.2}, Case{srkn14a(), 0.2}}) {
    const double coarse = kg_energy_error(law, chain, c.scheme, s0, c.tau, 100, 1);
    const double fine = kg_energy_error(law, chain, c.scheme, s0, c.tau / 2, 100, 1);
    const double expected = std::pow(2.0, c.scheme.order), ratio = coarse / fine;
    std::printf("  %s: tau %.3g: %.3e, tau/2: %.3e, ratio %.2f (2^%d = %.0f)\n", c.scheme.name.c_str(), c.tau, coarse,
                fine, ratio, c.scheme.order, expected);
    EXPECT_GT(ratio, 0.75 * expected) << c.scheme.name;
    EXPECT_LT(ratio, 1.25 * expected) << c.scheme.name;
    if (c.scheme.name == "saba2c") saba2c_error = coarse;
  }
  EXPECT_LT(saba2c_error, 2e-6);  // at τ = 0.1: 1.47e-6 measured
}

// At amplitude 1e-5 the quartic term shifts a mode's ω by ~(3/8) 1e-10 Σ v⁴ / ω² < 1e-10 relative:
// the motion projected on an eigenvector of the linear problem written out here (ε̃_l + 2/W on the
// diagonal, −1/W beside it: fixed ends x_0 = x_{N+1} = 0) oscillates at the square root of its
// eigenvalue, measured from 40 periods of upward zero crossings.
TEST(KleinGordonDynamics, TinyAmplitudeModesOscillateAtTheLinearFrequencies) {
  const std::size_t n = 32;
  const KleinGordonParameters p{.N = n, .W = kg_w, .seed = 3};
  const Chain chain = klein_gordon(p);
  const ForceLaw law = kg_law(chain);
  SymTridiagonal a;
  for (double e : klein_gordon_disorder(p)) a.diagonal.push_back(e + 2 / kg_w);
  a.off_diagonal.assign(n - 1, -1 / kg_w);
  const EigenDecomposition modes = LapackEigensolver().solve(a, true);
  for (std::size_t j : {std::size_t{0}, n / 2, n - 1}) {
    const auto jj = static_cast<Eigen::Index>(j);
    const double omega = std::sqrt(modes.values[jj]);
    const auto v = [&](std::size_t i) { return modes.vectors(static_cast<Eigen::Index>(i), jj); };
    State s0(n);
    for (std::size_t i = 0; i < n; ++i) s0.u[i] = 1e-5 * v(i);
    const double period = 2 * std::numbers::pi / omega, tau = period / 400;
    auto prop = make_splitting_propagator(law, chain, saba2c(), tau, s0, {.enabled = false});
    const auto projection = [&] {
      double q = 0;
      for (std::size_t i = 0; i < n; ++i) q += v(i) * prop->displacement()[i];
      return q;
    };
    std::vector<double> crossings;
    double before = projection();
    for (std::size_t step = 1; step <= 400 * 40; ++step) {
      prop->advance(1);
      const double now = projection();
      if (before < 0 && now >= 0) crossings.push_back((static_cast<double>(step - 1) + before / (before - now)) * tau);
      before = now;
    }
    ASSERT_GE(crossings.size(), 39u);
    const double measured =
        2 * std::numbers::pi * static_cast<double>(crossings.size() - 1) / (crossings.back() - crossings.front());
    const double error = std::abs(measured / omega - 1);
    std::printf("  mode %zu: omega %.12f, measured %.12f, relative %.2e\n", j + 1, omega, measured, error);
    EXPECT_LT(error, 1e-6);
  }
  // The library's dynamical matrix of the chain is the same linear problem.
  const auto d = dynamical_matrix(chain);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(d.diagonal[i], a.diagonal[i], 1e-15) << i;
  for (std::size_t i = 0; i + 1 < n; ++i) EXPECT_NEAR(d.off_diagonal[i], a.off_diagonal[i], 1e-15) << i;
}

// Energy density 1 on four sites: x⁴/4 is as large as ε̃ x²/2, strongly nonlinear. The deviation the
// tangent map carries is the central difference of two orbits started ±1e-6 w apart.
TEST(KleinGordonDynamics, TangentMapIsTheDifferenceOfTwoNearbyOrbits) {
  const Chain chain = kg_chain(16);
  const ForceLaw law = kg_law(chain);
  const State a = block_energy_kick(chain, 6, 4, 1.0, 1);
  const State w = kg_spread_deviation(chain.size());
  const double epsilon = 1e-6, tau = 0.05;
  const std::size_t steps = 400;  // t = 20
  State plus = a, minus = a;
  for (std::size_t i = 0; i < a.size(); ++i) {
    plus.u[i] += epsilon * w.u[i];
    plus.v[i] += epsilon * w.v[i];
    minus.u[i] -= epsilon * w.u[i];
    minus.v[i] -= epsilon * w.v[i];
  }
  for (const SplittingScheme& scheme : {saba2c(), aba864()}) {
    auto tangent = make_tangent_propagator(law, chain, scheme, tau, a, w,
                                           {.enabled = true, .renormalize_every = 0, .time_unit = 1});
    tangent->advance(steps);
    auto pa = fixtures::run(make_splitting_propagator(law, chain, scheme, tau, a, {.enabled = false}), steps);
    auto pp = fixtures::run(make_splitting_propagator(law, chain, scheme, tau, plus, {.enabled = false}), steps);
    auto pm = fixtures::run(make_splitting_propagator(law, chain, scheme, tau, minus, {.enabled = false}), steps);
    EXPECT_EQ(relative_difference(tangent->displacement(), pa->displacement()), 0.0);  // the same orbit
    const auto fd = fixtures::finite_difference_deviation(*pm, *pp, 2 * epsilon);
    const double eu = relative_difference(tangent->deviation_displacement(), fd.u);
    const double ev = relative_difference(tangent->deviation_velocity(), fd.v);
    const double moved = relative_difference(tangent->deviation_displacement(), w.u);
    std::printf("  %s: |dev - central difference| / |dev|: u %.2e, v %.2e (moved %.2f)\n", scheme.name.c_str(), eu, ev,
                moved);
    EXPECT_LT(eu, 1e-6);
    EXPECT_LT(ev, 1e-6);
    EXPECT_GT(moved, 0.1);
    // Further vectors (the kernels fed by the orbit's stored on-site Hessian and curvature) are what
    // the single-vector map makes of them, bit for bit.
    const std::vector<State> ws{kg_spread_deviation(chain.size()), a, plus};
    auto several = make_tangent_propagator(law, chain, scheme, tau, a, ws,
                                           {.enabled = true, .renormalize_every = 0, .time_unit = 1});
    several->advance(steps);
    for (std::size_t j = 0; j < ws.size(); ++j) {
      auto one = make_tangent_propagator(law, chain, scheme, tau, a, ws[j],
                                         {.enabled = true, .renormalize_every = 0, .time_unit = 1});
      one->advance(steps);
      EXPECT_EQ(relative_difference(several->deviation_displacement(j), one->deviation_displacement()), 0.0) << j;
      EXPECT_EQ(relative_difference(several->deviation_velocity(j), one->deviation_velocity()), 0.0) << j;
    }
  }
}

// The map of 2N unit vectors over t = 100 is symplectic: ‖Mᵀ J M − J‖ at rounding.
TEST(KleinGordonDynamics, TangentMapIsSymplectic) {
  const std::size_t n = 8;
  const Chain chain = kg_chain(n);
  const ForceLaw law = kg_law(chain);
  const State start = block_energy_kick(chain, 2, 4, 1.0, 2);
  std::vector<State> basis(2 * n, State(n));
  for (std::size_t c = 0; c < 2 * n; ++c) (c < n ? basis[c].u[c] : basis[c].v[c - n]) = 1;
  for (const SplittingScheme& scheme : {saba2c(), aba864()}) {
    auto map = make_tangent_propagator(law, chain, scheme, 0.05, start, basis,
                                       {.enabled = true, .renormalize_every = 0, .time_unit = 1});
    map->advance(2000);
    std::vector<double> m(4 * n * n);  // M[r][c]
    double largest = 0;
    for (std::size_t c = 0; c < 2 * n; ++c)
      for (std::size_t r = 0; r < n; ++r) {
        m[r * 2 * n + c] = map->deviation_displacement(c)[r];
        m[(n + r) * 2 * n + c] = map->deviation_velocity(c)[r];
      }
    for (double x : m) largest = std::max(largest, std::abs(x));
    double worst = 0;
    for (std::size_t a = 0; a < 2 * n; ++a)
      for (std::size_t b = 0; b < 2 * n; ++b) {
        double x = 0;
        for (std::size_t i = 0; i < n; ++i)
          x += m[i * 2 * n + a] * m[(n + i) * 2 * n + b] - m[(n + i) * 2 * n + a] * m[i * 2 * n + b];
        const double j = (b == a + n) ? 1.0 : (a == b + n) ? -1.0 : 0.0;
        worst = std::max(worst, std::abs(x - j));
      }
    std::printf("  %s: max |M^T J M - J| = %.2e, max |M| = %.2e\n", scheme.name.c_str(), worst, largest);
    EXPECT_GT(largest, 2.0);
    EXPECT_LT(worst, 1e-12 * largest * largest);
  }
}

// The full spectrum of a 4-site chain at energy density 2 (chaotic): pairs λ_j = −λ_{2N+1−j}
// within the finite-time error (the largest change of any exponent between T/2 and T), sum zero.
// Measured at T = 10⁴: λ_1 = 0.0334, error 7.5e-4, the pairs' sums ≤ 2e-4, total 1e-16.
TEST(KleinGordonDynamics, FullLyapunovSpectrumComesInPairs) {
  const std::size_t n = 4;
  const Chain chain = kg_chain(n, 5);
  const ForceLaw law = kg_law(chain);
  const State start = block_energy_kick(chain, 0, n, 2.0, 3);
  LyapunovSpectrum spectrum(law, chain, saba2c(), 0.05, start,
                            {.vectors = 2 * n, .orthonormalize_every = 10, .time_unit = 1});
  spectrum.advance(100000);  // T/2 = 5000
  const std::vector<double> half = spectrum.exponents();
  spectrum.advance(100000);
  const std::vector<double> l = spectrum.exponents();
  double error = 0, sum = 0;
  for (std::size_t j = 0; j < l.size(); ++j) {
    error = std::max(error, std::abs(l[j] - half[j]));
    sum += l[j];
  }
  std::printf("  lambda(T = %.0f):", spectrum.time());
  for (double x : l) std::printf(" %.5f", x);
  std::printf("\n  finite-time error %.2e; sum %.2e\n", error, sum);
  const double top = l.front();
  EXPECT_GT(top, 10 * error);  // chaotic
  for (std::size_t j = 0; j < n; ++j) EXPECT_LT(std::abs(l[j] + l[2 * n - 1 - j]), error) << "pair " << j;
  EXPECT_LT(std::abs(sum), 1e-12 * top);
}

// The damped stepper's kernels (its own corrector with the on-site Hessian) with a damping time far
// beyond the run agree with the conservative stepper; the Odeint reference (its own force loop) too.
// Both differences would be O(1e-4) with the quartic part missing from a corrector or a force.
TEST(KleinGordonDynamics, DampedAndReferenceSteppersAgreeWithTheConservativeOne) {
  const Chain chain = kg_chain(32);
  const ForceLaw law = kg_law(chain);
  const State s0 = block_energy_kick(chain, 12, 8, 0.5, 4);
  const double tau = 0.01;
  const std::size_t steps = 2000;  // t = 20
  auto plain = fixtures::run(make_splitting_propagator(law, chain, saba2c(), tau, s0, {.enabled = false}), steps);
  auto damped = fixtures::run(make_damped_propagator(law, chain, saba2c(), tau, s0, {.time = 1e15}), steps);
  auto reference = fixtures::run(make_reference_propagator(law, chain, tau, s0, {1e-16, 1e-16, 0}), steps);
  Chain linear = chain;
  linear.onsite_quartic.clear();
  auto harmonic =
      fixtures::run(make_splitting_propagator(kg_law(linear), linear, saba2c(), tau, s0, {.enabled = false}), steps);
  const double damped_error = relative_difference(damped->displacement(), plain->displacement());
  const double reference_error = relative_difference(plain->displacement(), reference->displacement());
  const double without = relative_difference(harmonic->displacement(), reference->displacement());
  std::printf("  damped vs conservative %.2e, SABA2C vs reference %.2e, without the quartic part %.2e\n", damped_error,
              reference_error, without);
  EXPECT_LT(damped_error, 1e-10);
  EXPECT_LT(reference_error, 1e-8);
  EXPECT_GT(without, 1e-2);
  // Contact damping needs contacts: refused, naming its parameter.
  try {
    make_damped_propagator(law, chain, saba2c(), tau, s0, {.kk_gamma = 1e-3});
    ADD_FAILURE() << "contact damping accepted on linear springs";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "kk_gamma");
  }
}

// The active window (the stepper integrates only where the energy has arrived) relies on quiescent
// sites staying exactly at rest: the on-site force −ε̃ u − u³ and the bond force vanish at u = 0.
// One site in a chain of 400, t = 200: the window ends far inside and changes nothing.
TEST(KleinGordonDynamics, ActiveWindowChangesNothing) {
  const Chain chain = kg_chain(400);
  const ForceLaw law = kg_law(chain);
  const State s0 = site_energy_kick(chain, 199, 0.4);
  auto window = fixtures::run(make_splitting_propagator(law, chain, saba2c(), 0.1, s0), 2000);
  auto whole = fixtures::run(make_splitting_propagator(law, chain, saba2c(), 0.1, s0, {.enabled = false}), 2000);
  std::printf("  window [%zu, %zu) of %zu; difference %.2e\n", window->window_begin(), window->window_end(),
              chain.size(), relative_difference(window->displacement(), whole->displacement()));
  EXPECT_GT(window->window_begin(), 0u);
  EXPECT_LT(window->window_end(), chain.size());
  EXPECT_LT(relative_difference(window->displacement(), whole->displacement()), 1e-12);
  EXPECT_LT(relative_difference(window->velocity(), whole->velocity()), 1e-12);
}

}  // namespace
}  // namespace granular
