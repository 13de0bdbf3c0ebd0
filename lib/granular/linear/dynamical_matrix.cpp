#include "granular/linear/dynamical_matrix.hpp"

#include <cmath>
#include <numbers>

#include "granular/error.hpp"

namespace granular {

double linear_stiffness(double contact, double precompression) {
  return 1.5 * std::cbrt(contact * contact * precompression);
}

std::vector<double> linear_stiffness(const Chain& chain) {
  std::vector<double> b(chain.bonds());
  for (std::size_t k = 0; k < b.size(); ++k) b[k] = linear_stiffness(chain.contact[k], chain.precompression);
  return b;
}

SymTridiagonal dynamical_matrix(const Chain& chain) {
  if (!(chain.precompression > 0))
    throw InvalidInput("F0 = 0: the sonic vacuum has no linear spectrum (use F0 > 0)");
  const std::size_t n = chain.size();
  const auto b = linear_stiffness(chain);
  SymTridiagonal d;
  d.diagonal.resize(n);
  d.off_diagonal.resize(n - 1);
  for (std::size_t i = 0; i < n; ++i) d.diagonal[i] = (b[i] + b[i + 1]) * chain.inverse_mass[i];
  for (std::size_t i = 0; i + 1 < n; ++i)
    d.off_diagonal[i] = -b[i + 1] * std::sqrt(chain.inverse_mass[i] * chain.inverse_mass[i + 1]);
  return d;
}

double frequency_khz(double omega_squared) {
  return std::sqrt(std::fmax(omega_squared, 0.0)) / (2 * std::numbers::pi) * 1e-3;
}

}  // namespace granular
