// Half-period shooting and Floquet multipliers (docs/breathers.md): the shooting Jacobian is the
// derivative of the half-period map (central finite differences), and the monodromy matrix of the
// linearized chain has the multipliers e^{±iω_k T} of its linear modes (the linear spectrum,
// an independent computation), all on the unit circle.
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/dynamics_fixtures.hpp"
#include "granular/error.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/orbits/floquet.hpp"
#include "granular/orbits/periodic_orbit.hpp"

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
  EXPECT_LT(f.product_error, 1e-10);
}

// One rule for the +1 pair, dense and ARPACK alike (floquet.hpp): of the multipliers within
// unit_pair_window (1e-2) of +1, the two nearest. A real pair λ = 1.02, 1/λ with no pair at +1
// is an instability (a perturbation grows like λ^{t/T}), which the dense method once left out as
// "the two multipliers nearest +1" wherever they were, calling the matrix stable. Block diagonal
// (column-major): rotations by 0.3 and 1.1 rad, diag(λ, 1/λ), and optionally a Jordan block at +1.
TEST(Floquet, OnlyMultipliersNearOneAreThePhasePair) {
  const double lambda = 1.02;
  const auto matrix = [&](bool jordan) {
    const std::size_t m = jordan ? 8 : 6;
    std::vector<double> a(m * m, 0.0);
    const auto at = [&](std::size_t i, std::size_t j) -> double& { return a[j * m + i]; };
    for (const auto& [k, angle] : {std::pair<std::size_t, double>{0, 0.3}, {2, 1.1}}) {
      at(k, k) = at(k + 1, k + 1) = std::cos(angle);
      at(k, k + 1) = -std::sin(angle);
      at(k + 1, k) = std::sin(angle);
    }
    at(4, 4) = lambda;
    at(5, 5) = 1 / lambda;
    if (jordan) at(6, 6) = at(7, 7) = at(6, 7) = 1;
    return a;
  };
  const FloquetSpectrum without = floquet_spectrum(matrix(false), 3, 1.0);
  EXPECT_TRUE(unit_pair(without.multipliers, 1e-2).empty());
  EXPECT_NEAR(without.max_modulus, lambda, 1e-14);
  EXPECT_FALSE(without.stable);
  EXPECT_EQ(without.instability, "real");
  EXPECT_TRUE(std::isnan(without.unit_pair_distance));
  const FloquetSpectrum with = floquet_spectrum(matrix(true), 4, 1.0);
  const auto pair = unit_pair(with.multipliers, 1e-2);
  ASSERT_EQ(pair.size(), 2u);
  for (std::size_t i : pair) EXPECT_LT(std::abs(with.multipliers[i] - 1.0), 1e-7);
  EXPECT_NEAR(with.max_modulus, lambda, 1e-14);  // the Jordan pair left out, the real pair not
  EXPECT_FALSE(with.stable);
  // A third multiplier within the window is not the pair's: the two nearest are.
  const std::vector<std::complex<double>> three{1.009, {1, 1e-6}, {1, -1e-6}, 0.5};
  EXPECT_EQ(unit_pair(three, 1e-2), (std::vector<std::size_t>{1, 2}));
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
