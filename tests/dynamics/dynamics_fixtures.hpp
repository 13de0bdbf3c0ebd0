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

}  // namespace granular::fixtures
