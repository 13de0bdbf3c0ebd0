#include "granular/model/contact_law.hpp"

#include <cmath>
#include <limits>

#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {

double hertz_coefficient(const Material& a, double ra, const Material& b, double rb) {
  if (!(ra > 0) || !(rb > 0)) throw InvalidInput("radius", ": contact radii must be > 0");
  if (std::isinf(ra) && std::isinf(rb)) throw InvalidInput("radius", ": two flat walls have no Hertz contact");
  const double effective_radius = std::isinf(ra) ? rb : std::isinf(rb) ? ra : ra * rb / (ra + rb);
  const double compliance = b.young * (1 - a.poisson * a.poisson) + a.young * (1 - b.poisson * b.poisson);
  return 4.0 * a.young * b.young * std::sqrt(effective_radius) / (3.0 * compliance);
}

double static_overlap(double contact, double precompression) { return std::pow(precompression / contact, 2.0 / 3.0); }

double hertz_force(double contact, double overlap) {
  return overlap > 0 ? contact * overlap * std::sqrt(overlap) : 0.0;
}

double hertz_stiffness(double contact, double overlap) {
  return overlap > 0 ? 1.5 * contact * std::sqrt(overlap) : 0.0;
}

double hertz_energy(double contact, double overlap) {
  return overlap > 0 ? 0.4 * contact * overlap * overlap * std::sqrt(overlap) : 0.0;
}

double linear_stiffness(double contact, double precompression) {
  return 1.5 * std::cbrt(contact * contact * precompression);
}

FpuCoefficients fpu_coefficients(double a, double f0) {
  if (!(a > 0) || !std::isfinite(a)) throw InvalidInput("contact", " " + format_number(a) + ": must be finite and > 0");
  if (!(f0 > 0) || !std::isfinite(f0))
    throw InvalidInput("precompression", " " + format_number(f0) + ": the FPU expansion needs a finite F0 > 0");
  const double a23 = std::cbrt(a * a);
  return {linear_stiffness(a, f0), 0.375 * a23 * a23 / std::cbrt(f0), -(3.0 / 48.0) * a * a / f0};
}

double nonlinearity_ratio(double alpha, double a, double f0) {
  if (!std::isfinite(alpha)) throw InvalidInput("alpha", " " + format_number(alpha) + ": must be finite");
  if (!(a > 0) || !std::isfinite(a)) throw InvalidInput("contact", " " + format_number(a) + ": must be finite and > 0");
  if (!(f0 >= 0) || !std::isfinite(f0))
    throw InvalidInput("precompression", " " + format_number(f0) + ": must be finite and >= 0");
  if (f0 == 0) return std::numeric_limits<double>::infinity();
  return std::fabs(alpha) / static_overlap(a, f0);
}

}  // namespace granular
