#include "granular/linear/band_edges.hpp"

#include <cmath>
#include <numbers>

#include "granular/error.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/model/contact_law.hpp"
#include "granular/model/disorder.hpp"

namespace granular {

BandEdges band_edges(const Material& material, double r1, double xi, double f0) {
  validate(material, "material");
  validate_size_ratio(xi);
  if (!(f0 > 0) || !std::isfinite(f0)) throw InvalidInput("F0", ": band edges need a finite F0 > 0");
  if (!(r1 > 0) || !std::isfinite(r1)) throw InvalidInput("R1", ": must be finite and > 0");
  const double r2 = xi * r1;
  auto mass = [&](double r) { return material.density * (4.0 / 3.0) * std::numbers::pi * r * r * r; };
  const double m1 = mass(r1), m2 = mass(r2), m3 = m1 * m2 / (m1 + m2);
  const double b11 = linear_stiffness(hertz_coefficient(material, r1, material, r1), f0);
  const double b22 = linear_stiffness(hertz_coefficient(material, r2, material, r2), f0);
  const double b12 = linear_stiffness(hertz_coefficient(material, r1, material, r2), f0);
  const double two_pi = 2 * std::numbers::pi;
  return {std::sqrt(4 * b11 / m1) / two_pi, std::sqrt(4 * b22 / m2) / two_pi, std::sqrt(2 * b12 / m1) / two_pi,
          std::sqrt(2 * b12 / m2) / two_pi, std::sqrt(2 * b12 / m3) / two_pi};
}

}  // namespace granular
