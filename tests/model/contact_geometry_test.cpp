// The elliptical Hertz contact of crossed cylinders (model/contact_geometry.hpp) against an exact
// limit, an independent evaluation of the same formulas, and Johnson's closed-form approximation.
#include "granular/model/contact_geometry.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "granular/model/contact_law.hpp"

namespace granular {
namespace {

constexpr double R = 4.76e-3, pi = std::numbers::pi;

double degrees(double d) { return d * pi / 180; }

TEST(ContactGeometry, CrossedCylindersAtRightAnglesAreASphereOnAFlat) {
  // At α = 90°, A = B = 1/(2R): the gap of a sphere of radius R on a plane, so the coefficient is
  // the sphere–wall one, (4/3) E* sqrt(R).
  const ContactGeometry g = crossed_cylinders(R, pi / 2);
  EXPECT_NEAR(g.A, 1 / (2 * R), 1e-12 / R);
  EXPECT_NEAR(g.B, 1 / (2 * R), 1e-12 / R);
  const double sphere_on_flat = hertz_coefficient(steel, R, steel, flat_wall);
  EXPECT_NEAR(hertz_coefficient(steel, steel, g) / sphere_on_flat, 1, 1e-14);
  // Near 90° (the small-eccentricity series) the coefficient is continuous and just above it: 90°
  // is its minimum (the effective radius R/sin α grows as the axes turn parallel).
  const double near = hertz_coefficient(steel, steel, crossed_cylinders(R, degrees(89.9)));
  EXPECT_GT(near, sphere_on_flat);
  EXPECT_NEAR(near / sphere_on_flat, 1, 1e-5);
}

TEST(ContactGeometry, SupplementaryAnglesGiveTheSameContact) {
  for (double a : {10.0, 30.0, 60.0, 85.0})
    EXPECT_NEAR(hertz_coefficient(steel, steel, crossed_cylinders(R, degrees(a))) /
                    hertz_coefficient(steel, steel, crossed_cylinders(R, degrees(180 - a))),
                1, 1e-13);
}

/// K(e) and E(e) by Gauss–Legendre-free composite Simpson on 20000 panels (independent of <cmath>).
double simpson(double e, bool first_kind) {
  const int n = 20000;
  double s = 0;
  for (int i = 0; i <= n; ++i) {
    const double t = pi / 2 * i / n, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    const double root = std::sqrt(1 - e * e * std::sin(t) * std::sin(t));
    s += w * (first_kind ? 1 / root : root);
  }
  return s * (pi / 2) / n / 3;
}

TEST(ContactGeometry, CoefficientSolvesJohnsonsEquationsIndependently) {
  // Solve B/A = [E/(1−e²) − K]/(K − E) by bisection in e with quadrature integrals, then
  // C = (2π E*/(3K)) sqrt((K − E)/(K e² A)).
  const double estar = 1 / (2 * (1 - 0.09) / 193e9);
  for (double a : {20.0, 45.0, 70.0}) {
    const ContactGeometry g = crossed_cylinders(R, degrees(a));
    const auto f = [&](double e) {
      const double k = simpson(e, true), ee = simpson(e, false);
      return (ee / (1 - e * e) - k) / (k - ee) - g.B / g.A;
    };
    double lo = 1e-3, hi = 1 - 1e-9;
    for (int i = 0; i < 60; ++i) (f(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
    const double e1 = 0.5 * (lo + hi);
    EXPECT_NEAR(contact_eccentricity(g), e1, 1e-9) << a;
    const double k = simpson(e1, true), ee = simpson(e1, false);
    const double c = 2 * pi * estar / (3 * k) * std::sqrt((k - ee) / (k * e1 * e1 * g.A));
    EXPECT_NEAR(hertz_coefficient(steel, steel, g) / c, 1, 1e-8) << a;
  }
}

TEST(ContactGeometry, AgreesWithJohnsonsEquivalentRadiusApproximation) {
  // Johnson eq. 4.45–4.46: δ ≈ (9P²/(16 Re E*²))^{1/3} F2 with Re = 1/(2 sqrt(AB)) and
  // F2 ≈ 1 − [(B/A)^0.0602 − 1]^1.456, good to a few per cent for B/A up to ~10; so
  // C ≈ (4/3) E* sqrt(Re) F2^{-3/2}.
  const double estar = 1 / (2 * (1 - 0.09) / 193e9);
  for (double a : {30.0, 45.0, 60.0, 80.0}) {
    const ContactGeometry g = crossed_cylinders(R, degrees(a));
    const double re = 1 / (2 * std::sqrt(g.A * g.B));
    const double f2 = 1 - std::pow(std::pow(g.B / g.A, 0.0602) - 1, 1.456);
    const double approx = 4.0 / 3 * estar * std::sqrt(re) / std::pow(f2, 1.5);
    EXPECT_NEAR(hertz_coefficient(steel, steel, g) / approx, 1, 0.02) << a;
  }
}

TEST(ContactGeometry, CoefficientGrowsAsTheAxesTurnParallel) {
  // Values of C/E* at R = 1 m from an independent evaluation (SciPy's ellipk/ellipe and brentq):
  // 1.3470 at 80°, 1.6874 at 45°, 2.8415 at 20°, 8.2421 at 5°.
  const double estar = 1 / (2 * (1 - 0.09) / 193e9);
  const double expected[][2] = {{80, 1.3470225525}, {45, 1.6873601538}, {20, 2.8415431303}, {5, 8.2420593053}};
  for (const auto& [a, c] : expected)
    EXPECT_NEAR(hertz_coefficient(steel, steel, crossed_cylinders(1.0, degrees(a))) / estar, c, 1e-8) << a;
}

// The ellipse's major semi-axis: the circle's √(δ R) of a sphere on a flat at 90°; at any angle
// the one Johnson's load relation gives from the coefficient, a = 3 K(e) C √δ / (2π E*) (from
// P = (2/3)π a b p0 and δ = p0 b K(e)/E*, eqs. 4.36–4.40), where the function reads A instead;
// growing without bound as the axes turn parallel.
TEST(ContactGeometry, SemiMajorAxisIsJohnsons) {
  const double delta = 1e-6;
  EXPECT_NEAR(contact_semi_major_axis(crossed_cylinders(R, pi / 2), delta), std::sqrt(delta * R), 1e-12 * R);
  const double effective = 1 / (2 * (1 - steel.poisson * steel.poisson) / steel.young);
  double previous = 0;
  for (double angle : {80.0, 45.0, 20.0, 5.0, 1.0, 0.45}) {
    const ContactGeometry g = crossed_cylinders(R, degrees(angle));
    const double e = contact_eccentricity(g), k = std::comp_ellint_1(e);
    const double from_load = 3 * k * hertz_coefficient(steel, steel, g) * std::sqrt(delta) / (2 * pi * effective);
    const double a = contact_semi_major_axis(g, delta);
    EXPECT_NEAR(a / from_load, 1, 1e-12) << angle;
    EXPECT_GT(a, previous) << angle;
    previous = a;
  }
  EXPECT_EQ(contact_semi_major_axis(crossed_cylinders(R, pi / 4), 0), 0);
  EXPECT_THROW(contact_semi_major_axis(crossed_cylinders(R, pi / 4), -1e-9), InvalidInput);
}

TEST(ContactGeometry, RejectsParallelAxesAndBadRadii) {
  EXPECT_THROW(crossed_cylinders(R, 0), InvalidInput);
  EXPECT_THROW(crossed_cylinders(R, pi), InvalidInput);
  EXPECT_THROW(crossed_cylinders(-R, 1), InvalidInput);
  EXPECT_THROW(hertz_coefficient(steel, steel, ContactGeometry{0, 1}), InvalidInput);
}

}  // namespace
}  // namespace granular
