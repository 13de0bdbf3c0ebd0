#include "granular/dynamics/initial_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "granular/dynamics/observables.hpp"
#include "granular/error.hpp"
#include "granular/model/random_stream.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

void check_site(const Chain& chain, std::size_t site) {
  if (site >= chain.size())
    throw InvalidInput("site", " " + std::to_string(site + 1) + ": outside the chain of " +
                                   std::to_string(chain.size()) + " beads (counting from 1)");
}

void check_overlap(const Chain& chain, std::span<const double> u, const char* parameter, double value) {
  for (std::size_t k = 0; k <= chain.size(); ++k) {
    double radius = std::numeric_limits<double>::infinity();
    if (k > 0) radius = std::min(radius, chain.radius[k - 1]);
    if (k < chain.size()) radius = std::min(radius, chain.radius[k]);
    if (chain.overlap[k] + std::abs(bond_strain(u, k)) >= radius)
      throw InvalidInput(parameter, " " + format_number(value) + ": static overlap plus the strain of bond " +
                                        std::to_string(k) + " reaches the bead radius " + format_number(radius) +
                                        " m (beads would pass through each other)");
  }
}

/// shape / max|shape|, checked.
std::vector<double> unit_shape(const Chain& chain, std::span<const double> shape) {
  if (shape.size() != chain.size())
    throw InvalidInput("shape", ": " + std::to_string(shape.size()) + " entries for a chain of " +
                                    std::to_string(chain.size()) + " beads");
  double largest = 0;
  for (double x : shape) {
    if (!std::isfinite(x)) throw InvalidInput("shape", ": an entry is not finite");
    largest = std::max(largest, std::abs(x));
  }
  if (!(largest > 0)) throw InvalidInput("shape", ": all entries are zero");
  std::vector<double> unit(shape.begin(), shape.end());
  for (double& x : unit) x /= largest;
  return unit;
}

}  // namespace

State shaped_displacement(const Chain& chain, std::span<const double> shape, double amplitude) {
  if (!std::isfinite(amplitude) || !(amplitude > 0))
    throw InvalidInput("amplitude", " " + format_number(amplitude) + ": must be finite and > 0 [m]");
  State s(chain.size());
  s.u = unit_shape(chain, shape);
  for (double& x : s.u) x *= amplitude;
  check_overlap(chain, s.u, "amplitude", amplitude);
  return s;
}

double shaped_amplitude_for_energy(const ForceLaw& law, const Chain& chain, std::span<const double> shape,
                                   double energy) {
  if (!std::isfinite(energy) || !(energy > 0))
    throw InvalidInput("energy", " " + format_number(energy) + ": must be finite and > 0 [J]");
  const std::vector<double> unit = unit_shape(chain, shape);
  // Largest amplitude before some bond's overlap reaches a radius: the bracket's ceiling.
  double ceiling = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k <= chain.size(); ++k) {
    double radius = std::numeric_limits<double>::infinity();
    if (k > 0) radius = std::min(radius, chain.radius[k - 1]);
    if (k < chain.size()) radius = std::min(radius, chain.radius[k]);
    const double strain = std::abs(bond_strain(unit, k));
    if (strain > 0) ceiling = std::min(ceiling, (radius - chain.overlap[k]) / strain);
  }
  const auto energy_at = [&](double a) {
    State s(chain.size());
    for (std::size_t n = 0; n < unit.size(); ++n) s.u[n] = a * unit[n];
    return total_energy(law, chain, s);
  };
  double lo = 0, hi = std::min(ceiling * (1 - 1e-9), 1e-9);
  while (energy_at(hi) < energy) {  // bracket by doubling, up to the ceiling
    if (hi >= ceiling * (1 - 1e-9))
      throw InvalidInput("energy",
                         " " + format_number(energy) + " J: not reached by this shape before the beads would overlap");
    lo = hi;
    hi = std::min(2 * hi, ceiling * (1 - 1e-9));
  }
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = (lo + hi) / 2;
    (energy_at(mid) < energy ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

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

State site_energy_kick(const Chain& chain, std::size_t site, double energy) {
  check_site(chain, site);
  if (!std::isfinite(energy) || !(energy > 0))
    throw InvalidInput("energy", " " + format_number(energy) + ": must be finite and > 0 [J]");
  State s(chain.size());
  s.v[site] = std::sqrt(2 * energy * chain.inverse_mass[site]);
  return s;
}

State block_energy_kick(const Chain& chain, std::size_t first, std::size_t length, double energy_density,
                        std::uint64_t seed, std::uint64_t realization) {
  check_site(chain, first);
  if (length == 0 || length > chain.size() - first)
    throw InvalidInput("length", " " + std::to_string(length) + ": the block of beads " + std::to_string(first + 1) +
                                     " … must hold at least one bead and end inside the chain of " +
                                     std::to_string(chain.size()));
  if (!std::isfinite(energy_density) || !(energy_density > 0))
    throw InvalidInput("energy_density", " " + format_number(energy_density) + ": must be finite and > 0 [J]");
  // A counter range of its own, far beyond any chain's draws from the same (seed, realization).
  constexpr std::uint64_t sign_block = std::uint64_t{1} << 60;  // uniform 2⁶² is the first of block 2⁶⁰
  const RandomStream stream(seed, realization);
  State s(chain.size());
  for (std::size_t j = 0; j < length; ++j) {
    const double uniform = stream.uniform_block(sign_block + j / 4)[j % 4];
    const double speed = std::sqrt(2 * energy_density * chain.inverse_mass[first + j]);
    s.v[first + j] = uniform < 0.5 ? -speed : speed;
  }
  return s;
}

double matched_velocity(const ForceLaw& law, const Chain& chain, std::size_t site, double alpha) {
  const double energy = total_energy(law, chain, displacement_kick(chain, site, alpha));
  if (!(energy > 0)) throw InvalidInput("alpha", " " + format_number(alpha) + ": the kick carries no energy");
  return std::sqrt(2 * energy / chain.mass[site]);
}

}  // namespace granular
