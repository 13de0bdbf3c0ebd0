// Half-period shooting and Floquet multipliers (docs/breathers.md): the shooting Jacobian is the
// derivative of the half-period map (central finite differences), and the monodromy matrix of the
// linearized chain has the multipliers e^{±iω_k T} of its linear modes (the linear spectrum,
// an independent computation), all on the unit circle.
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics_fixtures.hpp"
#include "granular/dynamics/floquet.hpp"
#include "granular/dynamics/periodic_orbit.hpp"
#include "granular/error.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"

namespace granular {
namespace {

std::vector<double> profile(const Chain& chain, double scale) {
  std::vector<double> x(chain.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = scale * std::sin(1.3 * static_cast<double>(i) + 0.4);
  return x;
}

TEST(PeriodicOrbit, JacobianIsTheDerivativeOfTheHalfPeriodMap) {
  const Chain chain = fixtures::anderson(9, 1.0);
  for (ForceLawKind kind : {ForceLawKind::hertz, ForceLawKind::fpu}) {
    const ForceLaw law = make_force_law(kind, chain);
    const double omega = 2 * std::numbers::pi * 6e3;
    const auto x0 = profile(chain, 0.3 * chain.overlap[0]);  // strongly nonlinear, contacts closed
    const std::size_t steps = shooting_steps(chain, omega);
    const auto exact = half_period_map(law, chain, saba2c(), steps, omega, x0, true);
    const std::size_t n = chain.size();
    const double h = 1e-5 * chain.overlap[0];
    double worst = 0, scale = 0;
    for (double v : exact.jacobian) scale = std::max(scale, std::abs(v));
    for (std::size_t j = 0; j < n; ++j) {
      auto plus = x0, minus = x0;
      plus[j] += h;
      minus[j] -= h;
      const auto vp = half_period_map(law, chain, saba2c(), steps, omega, plus, false).velocity;
      const auto vm = half_period_map(law, chain, saba2c(), steps, omega, minus, false).velocity;
      for (std::size_t i = 0; i < n; ++i)
        worst = std::max(worst, std::abs((vp[i] - vm[i]) / (2 * h) - exact.jacobian[j * n + i]));
    }
    EXPECT_LT(worst / scale, 1e-6) << to_string(kind);
  }
}

TEST(Floquet, LinearChainMultipliersAreItsModesRotations) {
  const Chain chain = fixtures::anderson(12, 10.0);
  const ForceLaw law = make_force_law(ForceLawKind::linear, chain);
  const Spectrum modes = spectrum(dynamical_matrix(chain));
  PeriodicOrbit orbit;  // any orbit: the linear tangent map does not depend on it
  orbit.omega = 2 * std::numbers::pi * modes.freq_khz[3] * 1e3 * 0.9;
  orbit.period = 2 * std::numbers::pi / orbit.omega;
  orbit.steps_per_period = 1024;
  orbit.time_step = orbit.period / 1024;
  orbit.scheme = saba2c();
  orbit.x0 = profile(chain, 1e-8);
  const auto f = floquet_stability(law, chain, orbit);
  ASSERT_EQ(f.multipliers.size(), 2 * chain.size());
  for (const auto mu : f.multipliers) EXPECT_NEAR(std::abs(mu), 1.0, 1e-10);
  EXPECT_TRUE(f.stable);
  // Each linear mode k gives e^{±iω_k T}: match every expected multiplier to a computed one.
  for (std::size_t k = 0; k < modes.size(); ++k) {
    const double phase = std::sqrt(modes.omega2[k]) * orbit.period;
    for (double sign : {1.0, -1.0}) {
      const std::complex<double> expected = std::polar(1.0, sign * phase);
      double nearest = 1;
      for (const auto mu : f.multipliers) nearest = std::min(nearest, std::abs(mu - expected));
      EXPECT_LT(nearest, 1e-6) << "mode " << k + 1;
    }
  }
  EXPECT_LT(f.reciprocal_error, 1e-10);
  EXPECT_LT(f.conjugate_error, 1e-10);
  EXPECT_LT(f.product_error, 1e-10);
}

TEST(PeriodicOrbit, RefusesWhatItCannotDo) {
  const Chain chain = fixtures::anderson(9, 1.0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const double omega = 2 * std::numbers::pi * 6e3;
  EXPECT_THROW(find_periodic_orbit(law, chain, omega, std::vector<double>(9, 0.0)), InvalidInput);
  EXPECT_THROW(find_periodic_orbit(law, chain, -1.0, profile(chain, 1e-8)), InvalidInput);
  // Dense Newton beyond the dense limit (automatic would use Newton-Krylov there).
  EXPECT_THROW(find_periodic_orbit(law, chain, omega, profile(chain, 1e-8),
                                   {.max_dense_beads = 8, .newton = NewtonMethod::dense}),
               InvalidInput);
  // One Newton step from an arbitrary profile does not reach 1e-10: a NumericalError, not garbage.
  EXPECT_THROW(find_periodic_orbit(law, chain, omega, profile(chain, 0.3 * chain.overlap[0]), {.max_iterations = 1}),
               NumericalError);
  // The arclength corrector needs a step count fixed along the branch, and a tangent per bead.
  ArcPrediction arc{.x = profile(chain, 1e-8),
                    .omega = omega,
                    .tangent_x = std::vector<double>(9, 0.0),
                    .tangent_omega = 1};
  try {
    find_periodic_orbit_on_arc(law, chain, arc, {});
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "steps_per_period");
  }
  arc.tangent_x.pop_back();
  EXPECT_THROW(find_periodic_orbit_on_arc(law, chain, arc, {.steps_per_period = 256}), InvalidInput);
}

}  // namespace
}  // namespace granular
