#pragma once
// The one convention for a mode vector the solvers return (internal).
#include <cmath>
#include <cstddef>

namespace granular::detail {

/// Unit length and a fixed sign (largest entry > 0), so that methods and runs compare and diff.
inline void normalize_mode(double* w, std::size_t n) {
  double norm2 = 0;
  std::size_t big = 0;
  for (std::size_t q = 0; q < n; ++q) {
    norm2 += w[q] * w[q];
    if (std::fabs(w[q]) > std::fabs(w[big])) big = q;
  }
  const double f = (w[big] < 0 ? -1.0 : 1.0) / std::sqrt(norm2);
  for (std::size_t q = 0; q < n; ++q) w[q] *= f;
}

}  // namespace granular::detail
