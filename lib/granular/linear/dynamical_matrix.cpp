#include "granular/linear/dynamical_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "granular/error.hpp"
#include "granular/linear/mode_ipr.hpp"

namespace granular {

DynamicalMatrix dynamical_matrix(const Chain& chain) {
  // At F0 = 0 the bonds have no linear stiffness: beads on on-site springs still have a linear
  // spectrum (each bead's own ω_n² = k_n/m_n), the bare sonic vacuum has none.
  if (!(chain.precompression > 0) && chain.onsite.empty())
    throw InvalidInput("precompression", " 0: the sonic vacuum has no linear spectrum (needs F0 > 0)");
  const std::size_t n = chain.size();
  const auto b = linear_stiffness(chain);
  DynamicalMatrix d;
  d.diagonal.resize(n);
  d.off_diagonal.resize(n - 1);
  for (std::size_t i = 0; i < n; ++i) d.diagonal[i] = (b[i] + b[i + 1]) * chain.inverse_mass[i];
  if (!chain.onsite.empty())  // a spring to the ground adds k_n/m_n to its bead's row
    for (std::size_t i = 0; i < n; ++i) d.diagonal[i] += chain.onsite[i] * chain.inverse_mass[i];
  for (std::size_t i = 0; i + 1 < n; ++i)
    d.off_diagonal[i] = -b[i + 1] * std::sqrt(chain.inverse_mass[i] * chain.inverse_mass[i + 1]);
  d.inverse_sqrt_mass = inverse_sqrt_mass(chain.inverse_mass);
  return d;
}

DynamicalMatrix dynamical_matrix(const BeadSource& beads) {
  const std::size_t n = beads.size(), piece = 65536;
  DynamicalMatrix d;
  d.diagonal.resize(n);
  d.off_diagonal.resize(n - 1);
  d.inverse_sqrt_mass.resize(n);
  std::vector<double> mass(piece), b(piece + 1), onsite(piece);
  double previous_inverse_mass = 0;
  for (std::size_t first = 0; first < n; first += piece) {
    const std::size_t count = std::min(piece, n - first);
    beads.read(first, count, mass.data(), b.data());
    if (beads.grounded()) beads.read_onsite(first, count, onsite.data());
    for (std::size_t j = 0; j < count; ++j) {  // the operations of dynamical_matrix(Chain), in its order
      const std::size_t i = first + j;
      const double inverse_mass = 1.0 / mass[j];
      d.diagonal[i] = (b[j] + b[j + 1]) * inverse_mass;
      if (beads.grounded()) d.diagonal[i] += onsite[j] * inverse_mass;
      if (i > 0) d.off_diagonal[i - 1] = -b[j] * std::sqrt(previous_inverse_mass * inverse_mass);
      d.inverse_sqrt_mass[i] = std::sqrt(inverse_mass);
      previous_inverse_mass = inverse_mass;
    }
  }
  return d;
}

double frequency_khz(double omega_squared) {
  return std::sqrt(std::fmax(omega_squared, 0.0)) / (2 * std::numbers::pi) * 1e-3;
}

double omega_squared_of_khz(double khz) {
  const double omega = 2 * std::numbers::pi * khz * 1e3;
  return omega * omega;
}

}  // namespace granular
