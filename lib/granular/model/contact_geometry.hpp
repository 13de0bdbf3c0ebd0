#pragma once
// The Hertz contact of two smooth elastic bodies of any curvature (docs/physics.md, "Quasiperiodic
// chains"): the gap between them near the first point of contact is h = A x² + B y² (Johnson,
// Contact Mechanics, §4.2), the contact is an ellipse and the force is still P = C δ^{3/2}, with C
// from A, B and the effective modulus through the complete elliptic integrals K(e), E(e) of the
// ellipse's eccentricity e. Two spheres are the case A = B (a circle, contact_law.hpp's
// hertz_coefficient); two cylinders whose axes cross at an angle α are the case the quasiperiodic
// cylinder chain (quasiperiodic.hpp) needs, one coefficient per bond from that bond's angle.
#include "granular/model/material.hpp"

namespace granular {

/// The relative curvatures of a contact: h = A x² + B y² [1/m], 0 < A ≤ B.
struct ContactGeometry {
  double A;
  double B;
};

/// Two equal cylinders of radius R [m] whose axes cross at angle α [rad] in (0, π):
/// A + B = 1/R, B − A = |cos α|/R (Johnson eq. 4.30 with one zero curvature per body).
ContactGeometry crossed_cylinders(double radius, double angle);

/// The eccentricity e = sqrt(1 − b²/a²) of the contact ellipse of a geometry: the root of
/// B/A = [E(e)/(1 − e²) − K(e)] / [K(e) − E(e)] (Johnson eq. 4.39), found by bisection.
double contact_eccentricity(const ContactGeometry& g);

/// The major semi-axis a [m] of the contact ellipse at overlap δ [m] (Johnson eqs. 4.36–4.40):
/// a = √(δ (K − E)/(K e² A)); for spheres (A = B = 1/(2R*)) the circle's √(δ R*). It lies along
/// the direction of the smaller curvature A, which for cylinders turning parallel is along their
/// axes: the size to hold against the bodies' for the point-contact law to apply
/// (quasiperiodic.hpp, cylinder_ellipse_limit). Throws InvalidInput as contact_eccentricity, and
/// ("overlap") unless δ ≥ 0 finite.
double contact_semi_major_axis(const ContactGeometry& g, double overlap);

/// C [N/m^{3/2}] with P = C δ^{3/2}: C = (2π E*/(3K)) sqrt((K − E)/(K e² A)), where
/// 1/E* = (1−ν_a²)/E_a + (1−ν_b²)/E_b. Reduces to (4/3) E* sqrt(R) for A = B = 1/(2R).
/// Throws InvalidInput ("radius") unless 0 < A ≤ B finite.
double hertz_coefficient(const Material& a, const Material& b, const ContactGeometry& g);

}  // namespace granular
