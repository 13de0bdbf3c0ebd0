#include "granular/dynamics/initial_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "granular/dynamics/observables.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

void check_site(const Chain& chain, std::size_t site) {
  if (site >= chain.size())
    throw InvalidInput("site", " " + std::to_string(site + 1) + ": outside the chain of " +
                                   std::to_string(chain.size()) + " beads (counting from 1)");
}

}  // namespace

State displacement_kick(const Chain& chain, std::size_t site, double alpha) {
  check_site(chain, site);
  if (!std::isfinite(alpha) || alpha == 0)
    throw InvalidInput("alpha", " " + format_number(alpha) + ": must be finite and non-zero [m]");
  // Bond `site` joins bead site−1 (or the left wall) and bead site; bond site+1 the next pair.
  for (std::size_t k : {site, site + 1}) {
    double radius = std::numeric_limits<double>::infinity();
    if (k > 0) radius = std::min(radius, chain.radius[k - 1]);
    if (k < chain.size()) radius = std::min(radius, chain.radius[k]);
    if (chain.overlap[k] + std::abs(alpha) >= radius)
      throw InvalidInput("alpha", " " + format_number(alpha) + ": static overlap plus |alpha| reaches the bead radius " +
                                      format_number(radius) + " m (beads would pass through each other)");
  }
  State s(chain.size());
  s.u[site] = alpha;
  return s;
}

State velocity_kick(const Chain& chain, std::size_t site, double beta) {
  check_site(chain, site);
  if (!std::isfinite(beta) || beta == 0)
    throw InvalidInput("beta", " " + format_number(beta) + ": must be finite and non-zero [m/s]");
  State s(chain.size());
  s.v[site] = beta;
  return s;
}

double matched_velocity(const ForceLaw& law, const Chain& chain, std::size_t site, double alpha) {
  const double energy = total_energy(law, chain, displacement_kick(chain, site, alpha));
  if (!(energy > 0)) throw InvalidInput("alpha", " " + format_number(alpha) + ": the kick carries no energy");
  return std::sqrt(2 * energy / chain.mass[site]);
}

}  // namespace granular
