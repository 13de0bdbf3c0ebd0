#pragma once
// Test chains and helpers of the dynamics tests, on top of the shared tests/fixtures.hpp.
// Random chains here use seed 1 (the tool's default), so a test's chain is the one
// `spreading --seed 1 --realization r` integrates.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "fixtures.hpp"
#include "granular/dynamics/damping.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/linear/detail/lapack_eigensolver.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"

namespace granular::fixtures {

inline Chain disordered(Disorder disorder, std::size_t n, double f0, std::uint64_t realization = 0, double xi = 0.5,
                        double q = 0.5) {
  return make_chain(radii_of(realization_configuration(disorder, q, n, 1, realization), r1, xi), f0);
}
inline Chain anderson(std::size_t n, double f0, std::uint64_t realization = 0) {
  return disordered(Disorder::anderson, n, f0, realization);
}

/// ‖a − b‖₂ / ‖b‖₂
inline double relative_difference(std::span<const double> a, std::span<const double> b) {
  double d = 0, s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d += (a[i] - b[i]) * (a[i] - b[i]);
    s += b[i] * b[i];
  }
  return std::sqrt(d / s);
}

/// Runs `p` for `steps` steps and returns it, for one-line use in tests.
inline std::unique_ptr<Propagator> run(std::unique_ptr<Propagator> p, std::size_t steps) {
  p->advance(steps);
  return p;
}

/// The deviation (δu, δv) the tangent map should carry, by finite differences of two orbits whose
/// starts differ by `epsilon` times the deviation's start: (b − a) / epsilon.
struct FiniteDifferenceDeviation {
  std::vector<double> u, v;
};
inline FiniteDifferenceDeviation finite_difference_deviation(const Propagator& a, const Propagator& b, double epsilon) {
  FiniteDifferenceDeviation d{std::vector<double>(a.displacement().size()), std::vector<double>(a.velocity().size())};
  for (std::size_t i = 0; i < d.u.size(); ++i) {
    d.u[i] = (b.displacement()[i] - a.displacement()[i]) / epsilon;
    d.v[i] = (b.velocity()[i] - a.velocity()[i]) / epsilon;
  }
  return d;
}

// Exact solution of M ü = −B u − (M/τ_d) u̇ (B with the on-site springs, if any): every mode k obeys q̈ + q̇/τ_d + ω_k² q
// = 0, so q(t) = e^{−t/(2τ_d)} [q0 cos ω_d t + (q̇0 + q0/(2τ_d)) sin(ω_d t)/ω_d], ω_d² = ω_k² − 1/(4τ_d²).
inline std::vector<double> damped_modal_solution(const Chain& chain, const State& s0, double t, double tau_d) {
  const EigenDecomposition e = LapackEigensolver().solve(dynamical_matrix(chain), true);
  const std::size_t n = chain.size();
  std::vector<double> u(n, 0.0);
  const double decay = std::exp(-t / (2 * tau_d));
  for (std::size_t k = 0; k < n; ++k) {
    const auto kk = static_cast<Eigen::Index>(k);
    const double omega = std::sqrt(e.values[kk] - 1 / (4 * tau_d * tau_d));
    double a = 0, b = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w = e.vectors(static_cast<Eigen::Index>(i), kk);
      a += w * std::sqrt(chain.mass[i]) * s0.u[i];
      b += w * std::sqrt(chain.mass[i]) * s0.v[i];
    }
    const double c = decay * (a * std::cos(omega * t) + (b + a / (2 * tau_d)) * std::sin(omega * t) / omega);
    for (std::size_t i = 0; i < n; ++i)
      u[i] += c * e.vectors(static_cast<Eigen::Index>(i), kk) / std::sqrt(chain.mass[i]);
  }
  return u;
}

// The damped run of `law` on `chain` from s0 to `duration` [s] at each step of `taus`, against the
// exact damped modes: within 1e-5, and second order (the Strang splitting) from one τ to the next.
inline void expect_second_order_to_exact_damped_modes(const ForceLaw& law, const Chain& chain, const State& s0,
                                                      double tau_d, double duration, std::initializer_list<double> taus,
                                                      const std::vector<double>& exact) {
  double previous = 0;
  for (double tau : taus) {
    const auto p = run(make_damped_propagator(law, chain, saba2c(), tau, s0, {tau_d, 0}), steps_for(duration, tau));
    const double error = relative_difference(p->displacement(), exact);
    std::printf("  tau = %g us: relative difference from the exact damped modes %.3e\n", tau * 1e6, error);
    EXPECT_LT(error, 1e-5);
    if (previous > 0) {
      EXPECT_GT(previous / error, 3.0);
      EXPECT_LT(previous / error, 5.0);
    }
    previous = error;
  }
}

// A damped run from s0 in `blocks` blocks of 0.1 ms (τ = 0.05 µs): the worst |H + dissipated − H0|/H0
// at the blocks' ends, and the fraction of H0 dissipated by the end.
struct DampedBalance {
  double worst = 0, lost = 0;
};
inline DampedBalance damped_energy_balance(const ForceLaw& law, const Chain& chain, const State& s0,
                                           const Damping& damping, int blocks) {
  const double h0 = total_energy(law, chain, s0);
  auto p = make_damped_propagator(law, chain, saba2c(), 0.05e-6, s0, damping);
  DampedBalance b;
  for (int k = 0; k < blocks; ++k) {
    p->advance(2000);
    const double h = total_energy(law, chain, p->state());
    b.worst = std::max(b.worst, std::abs(h + p->dissipated_energy() - h0) / h0);
  }
  b.lost = p->dissipated_energy() / h0;
  std::printf("  tau_d = %g s, gamma_KK = %g s: dissipated %.4f of H0, balance error %.2e\n", damping.time,
              damping.kk_gamma, b.lost, b.worst);
  return b;
}

}  // namespace granular::fixtures
