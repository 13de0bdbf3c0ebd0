#include "granular/model/correlation.hpp"

#include <cmath>
#include <limits>

namespace granular {

std::vector<double> cyclic_correlation(const Configuration& types, std::size_t max_distance) {
  const std::size_t n = types.size();
  std::vector<double> rho(max_distance + 1, std::numeric_limits<double>::quiet_NaN());
  if (n == 0) return rho;
  double ones = 0;
  for (auto t : types) ones += t == 2;
  const double mean = ones / static_cast<double>(n);
  const double variance = mean - mean * mean;  // v ∈ {0,1}: mean(v²) = mean(v)
  if (!(variance > 0)) return rho;
  for (std::size_t d = 0; d <= max_distance; ++d) {
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += (types[i] == 2) && (types[(i + d) % n] == 2);
    rho[d] = (sum / static_cast<double>(n) - mean * mean) / variance;
  }
  return rho;
}

double correlation_theory(Disorder disorder, double q, std::size_t d) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  switch (disorder) {
    case Disorder::homogeneous: return nan;
    case Disorder::anderson: return (q == 0 || q == 1) ? nan : (d == 0 ? 1.0 : 0.0);
    case Disorder::rdm1: return (q == 0 || q == 1) ? nan : d == 0 ? 1.0 : d == 1 ? 0.5 : 0.0;
    case Disorder::rdm2: {
      const double s = (2 * q - 1) * (2 * q - 1);
      if (d == 0) return 1.0;
      if (d == 1) return -0.5 * (s + 1);
      return (d % 2 == 0 ? 1.0 : -1.0) * s;
    }
  }
  return nan;
}

}  // namespace granular
