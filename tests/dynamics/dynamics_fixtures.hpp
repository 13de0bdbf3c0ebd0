#pragma once
// Test chains and helpers of the dynamics tests, on top of the shared tests/fixtures.hpp.
// Random chains here use seed 1 (the tool's default), so a test's chain is the one
// `spreading --seed 1 --realization r` integrates.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "fixtures.hpp"
#include "granular/dynamics/initial_conditions.hpp"
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

}  // namespace granular::fixtures
