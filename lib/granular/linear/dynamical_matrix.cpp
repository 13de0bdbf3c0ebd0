#include "granular/linear/dynamical_matrix.hpp"

#include <cmath>
#include <numbers>

#include "granular/error.hpp"
#include "granular/linear/mode_ipr.hpp"

namespace granular {

DynamicalMatrix dynamical_matrix(const Chain& chain) {
  if (!(chain.precompression > 0))
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

double frequency_khz(double omega_squared) {
  return std::sqrt(std::fmax(omega_squared, 0.0)) / (2 * std::numbers::pi) * 1e-3;
}

double omega_squared_of_khz(double khz) {
  const double omega = 2 * std::numbers::pi * khz * 1e3;
  return omega * omega;
}

}  // namespace granular
