// The product's regression values (docs/physics.md, "The linear spectrum", data/reference_values.csv).
#include <cmath>

#include <gtest/gtest.h>

#include "fixtures.hpp"
#include "granular/error.hpp"
#include "granular/linear/band_edges.hpp"
#include "granular/model/contact_law.hpp"

namespace granular {
namespace {

using fixtures::r1;
using fixtures::reference;

TEST(BandEdges, MatchSpecTableWithin1e3Khz) {
  const BandEdges e = band_edges(steel, r1, 0.5, 10);
  const std::pair<const char*, double> computed[] = {
      {"f1", e.f1}, {"f2", e.f2}, {"fb1", e.fb1}, {"fb2", e.fb2}, {"fb3", e.fb3}};
  for (const auto& [name, hz] : computed) {
    EXPECT_NEAR(hz * 1e-3, reference(name).value, 1e-3) << name;                       // the tolerance
    EXPECT_NEAR(hz * 1e-3, reference(name).value, reference(name).tolerance) << name;  // its printed digits
  }
}

TEST(BandEdges, ScaleAsF0ToTheOneSixthAndOrderCorrectly) {
  const BandEdges a = band_edges(steel, r1, 0.5, 10), b = band_edges(steel, r1, 0.5, 640);
  EXPECT_NEAR(b.f1 / a.f1, 2.0, 1e-12);  // B ∝ F0^{1/3}, f ∝ sqrt(B)
  EXPECT_LT(a.fb1, a.fb2);
  EXPECT_LT(a.fb2, a.fb3);
  const BandEdges h = band_edges(steel, r1, 1.0, 10);  // ξ = 1: the gap closes
  EXPECT_NEAR(h.fb1, h.fb2, 1e-9 * h.fb1);
  EXPECT_NEAR(h.fb3, h.f1, 1e-9 * h.f1);
  EXPECT_THROW(band_edges(steel, r1, 0.5, 0), InvalidInput);
  EXPECT_THROW(band_edges(steel, r1, 0, 10), InvalidInput);
}

TEST(WeakNonlinearity, FpuCoefficientsMatchSpec) {
  const FpuCoefficients b = fpu_coefficients(hertz_coefficient(steel, r1, steel, r1), 10);
  EXPECT_NEAR(b.b1, reference("B1").value, reference("B1").tolerance);
  EXPECT_NEAR(b.b2, reference("B2").value, reference("B2").tolerance);
  EXPECT_NEAR(b.b3, reference("B3").value, reference("B3").tolerance);
}

TEST(WeakNonlinearity, FpuCoefficientsAreTheHertzTaylorSeries) {
  // Independent check: finite differences of F(x) = A (Δ + x)^{3/2} − F0 at x = 0.
  const double a = 5.3e9, f0 = 3.0, delta = std::pow(f0 / a, 2.0 / 3.0), h = 1e-3 * delta;
  auto force = [&](double x) { return a * std::pow(delta + x, 1.5) - f0; };
  const FpuCoefficients b = fpu_coefficients(a, f0);
  EXPECT_NEAR((force(h) - force(-h)) / (2 * h), b.b1, 1e-6 * b.b1);
  EXPECT_NEAR((force(h) - 2 * force(0) + force(-h)) / (2 * h * h), b.b2, 1e-5 * b.b2);
  EXPECT_NEAR((force(2 * h) - 2 * force(h) + 2 * force(-h) - force(-2 * h)) / (12 * h * h * h), b.b3,
              1e-4 * std::fabs(b.b3));
}

TEST(WeakNonlinearity, HertzIsNeverModulationallyUnstable) {
  for (double f0 : {1e-3, 0.1, 1.0, 10.0, 1e3})
    for (double a : {1e8, 6.9e9, 1e11}) EXPECT_LT(fpu_coefficients(a, f0).modulational_discriminant(), 0);
}

TEST(WeakNonlinearity, NonlinearityRatioTable) {
  const double a11 = hertz_coefficient(steel, r1, steel, r1);
  const std::pair<const char*, double> table[] = {{"epsilon_F0_10", 10},
                                                  {"epsilon_F0_1", 1},
                                                  {"epsilon_F0_0.5", 0.5},
                                                  {"epsilon_F0_0.1", 0.1},
                                                  {"epsilon_F0_0.01", 0.01}};
  for (const auto& [name, f0] : table)
    EXPECT_NEAR(nonlinearity_ratio(1e-7, a11, f0), reference(name).value, reference(name).tolerance) << name;
  EXPECT_TRUE(std::isinf(nonlinearity_ratio(1e-7, a11, 0)));
}

TEST(WeakNonlinearity, EnergyMatchedVelocityKickOfSpec) {
  // β carries the energy of the displacement kick α: Σ of the two strained bond potentials
  // φ = (2/5) A ([Δ ∓ α]_+^{5/2} − Δ^{5/2}) ∓ F0 α (docs/physics.md, "Nonlinear dynamics") equals (1/2) m β².
  const Chain c = fixtures::homogeneous(11, 10);
  const double alpha = 1e-7, a = c.contact[5], d = c.overlap[5], f0 = 10;
  auto phi = [&](double x) { return 0.4 * a * (std::pow(std::fmax(d + x, 0.0), 2.5) - std::pow(d, 2.5)) - f0 * x; };
  const double energy = phi(-alpha) + phi(alpha);
  const double beta = std::sqrt(2 * energy / c.mass[5]);
  EXPECT_NEAR(beta, reference("beta_matched_F0_10").value, reference("beta_matched_F0_10").tolerance);
}

}  // namespace
}  // namespace granular
