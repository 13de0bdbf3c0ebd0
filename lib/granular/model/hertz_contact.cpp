#include "granular/model/hertz_contact.hpp"

#include <cmath>

#include "granular/error.hpp"

namespace granular {

double hertz_coefficient(const Material& a, double ra, const Material& b, double rb) {
  if (!(ra > 0) || !(rb > 0)) throw InvalidInput("hertz_coefficient: radii must be > 0");
  if (std::isinf(ra) && std::isinf(rb)) throw InvalidInput("hertz_coefficient: two flat walls have no Hertz contact");
  const double effective_radius = std::isinf(ra) ? rb : std::isinf(rb) ? ra : ra * rb / (ra + rb);
  const double compliance = b.young * (1 - a.poisson * a.poisson) + a.young * (1 - b.poisson * b.poisson);
  return 4.0 * a.young * b.young * std::sqrt(effective_radius) / (3.0 * compliance);
}

}  // namespace granular
