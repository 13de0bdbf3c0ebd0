#include "granular/model/contact_geometry.hpp"

#include <cmath>
#include <numbers>

#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

// Below this eccentricity K − E and E/(1−e²) − K lose digits to cancellation; their series
// (to e⁶, error O(e⁸) < 1e-16 relative) replace them.
constexpr double small_e = 1e-2;

/// (K − E)/e² and (E/(1 − e²) − K)/e², both → π/4 as e → 0.
struct Differences {
  double k_minus_e, e_over_minus_k, k;
};

Differences differences(double e) {
  const double e2 = e * e, half_pi = std::numbers::pi / 2;
  if (e < small_e)
    return {half_pi * (0.5 + 3.0 / 16 * e2 + 15.0 / 128 * e2 * e2),
            half_pi * (0.5 + 9.0 / 16 * e2 + 75.0 / 128 * e2 * e2),  // E/(1−e²) − K, its series
            half_pi * (1 + e2 / 4 + 9.0 / 64 * e2 * e2 + 25.0 / 256 * e2 * e2 * e2)};
  const double k = std::comp_ellint_1(e), ee = std::comp_ellint_2(e);
  return {(k - ee) / e2, (ee / (1 - e2) - k) / e2, k};
}

}  // namespace

ContactGeometry crossed_cylinders(double radius, double angle) {
  if (!(radius > 0) || !std::isfinite(radius))
    throw InvalidInput("radius", " " + format_number(radius) + ": must be finite and > 0");
  if (!(angle > 0) || !(angle < std::numbers::pi))
    throw InvalidInput("angle", " " + format_number(angle * 180 / std::numbers::pi) +
                                    " degrees: crossed cylinders need an angle in (0, 180)");
  const double c = std::fabs(std::cos(angle));
  return {(1 - c) / (2 * radius), (1 + c) / (2 * radius)};
}

double contact_eccentricity(const ContactGeometry& g) {
  if (!(g.A > 0) || !(g.B >= g.A) || !std::isfinite(g.B))
    throw InvalidInput("radius", ": a Hertz contact needs curvatures 0 < A <= B, finite");
  const double ratio = g.B / g.A;
  if (ratio == 1) return 0;
  // B/A grows monotonically from 1 (e = 0) to ∞ (e → 1); bisect in u = −ln(1 − e²) so that
  // very elongated ellipses (e within 1e-30 of 1) are found as precisely as round ones.
  const auto ratio_at = [](double u) {
    const double e = std::sqrt(-std::expm1(-u));
    const Differences d = differences(e);
    return d.e_over_minus_k / d.k_minus_e;
  };
  double lo = 0, hi = 1;
  while (ratio_at(hi) < ratio) {
    hi *= 2;
    if (hi > 1400) throw InvalidInput("angle", ": the contact ellipse is too elongated (B/A > 1e300)");
  }
  for (int i = 0; i < 200 && hi - lo > 1e-16 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ratio_at(mid) < ratio ? lo : hi) = mid;
  }
  return std::sqrt(-std::expm1(-0.5 * (lo + hi)));
}

double contact_semi_major_axis(const ContactGeometry& g, double overlap) {
  if (!(overlap >= 0) || !std::isfinite(overlap))
    throw InvalidInput("overlap", " " + format_number(overlap) + ": must be finite and >= 0");
  const Differences d = differences(contact_eccentricity(g));
  return std::sqrt(overlap * d.k_minus_e / (d.k * g.A));
}

double hertz_coefficient(const Material& a, const Material& b, const ContactGeometry& g) {
  const double e = contact_eccentricity(g);
  const Differences d = differences(e);
  const double effective_modulus = 1 / ((1 - a.poisson * a.poisson) / a.young + (1 - b.poisson * b.poisson) / b.young);
  return 2 * std::numbers::pi * effective_modulus / (3 * d.k) * std::sqrt(d.k_minus_e / (d.k * g.A));
}

}  // namespace granular
