#include "granular/analysis/log_derivative.hpp"

#include <algorithm>
#include <cmath>

#include "granular/error.hpp"

namespace granular {

LogDerivative log_derivative(const std::vector<double>& t, const std::vector<double>& y, double min_log_step) {
  if (t.size() != y.size()) throw InvalidInput("log_derivative: t and y differ in length");
  LogDerivative d;
  std::size_t j = 0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    if (!(t[i] > 0 && y[i] > 0)) continue;
    j = std::max(j, i + 1);
    while (j < t.size() && !(t[j] > t[i] && std::log(t[j] / t[i]) >= min_log_step)) ++j;
    if (j == t.size()) break;
    if (!(y[j] > 0)) continue;
    d.t.push_back(std::sqrt(t[i] * t[j]));
    d.slope.push_back(std::log(y[j] / y[i]) / std::log(t[j] / t[i]));
  }
  return d;
}

}  // namespace granular
