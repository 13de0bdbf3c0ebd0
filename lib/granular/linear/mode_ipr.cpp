#include "granular/linear/mode_ipr.hpp"

#include <cmath>

namespace granular {

double displacement_ipr(const double* w, const double* s, std::size_t n) {
  double sum2 = 0, sum4 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = w[i] * s[i];
    const double v2 = v * v;
    sum2 += v2;
    sum4 += v2 * v2;
  }
  return sum4 / (sum2 * sum2);
}

std::vector<double> inverse_sqrt_mass(const std::vector<double>& inverse_mass) {
  std::vector<double> s(inverse_mass.size());
  for (std::size_t i = 0; i < s.size(); ++i) s[i] = std::sqrt(inverse_mass[i]);
  return s;
}

}  // namespace granular
