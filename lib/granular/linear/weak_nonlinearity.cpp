#include "granular/linear/weak_nonlinearity.hpp"

#include <cmath>
#include <limits>

#include "granular/error.hpp"

namespace granular {

FpuCoefficients fpu_coefficients(double a, double f0) {
  if (!(a > 0) || !(f0 > 0) || !std::isfinite(a) || !std::isfinite(f0))
    throw InvalidInput("FPU coefficients need A > 0 and F0 > 0");
  const double a23 = std::cbrt(a * a);
  return {1.5 * a23 * std::cbrt(f0), 0.375 * a23 * a23 / std::cbrt(f0), -(3.0 / 48.0) * a * a / f0};
}

double static_overlap(double a, double f0) { return std::pow(f0 / a, 2.0 / 3.0); }

double nonlinearity_ratio(double alpha, double a, double f0) {
  if (!(f0 >= 0) || !(a > 0)) throw InvalidInput("nonlinearity ratio needs A > 0 and F0 >= 0");
  if (f0 == 0) return std::numeric_limits<double>::infinity();
  return std::fabs(alpha) / static_overlap(a, f0);
}

}  // namespace granular
