#include "granular/analysis/power_law_fit.hpp"

#include <cmath>
#include <string>

#include "granular/error.hpp"

namespace granular {

std::vector<double> log_derivative(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<double> d;
  for (std::size_t i = 1; i < t.size(); ++i)
    d.push_back(std::log(y[i] / y[i - 1]) / std::log(t[i] / t[i - 1]));
  return d;
}

PowerLawFit fit_power_law(const std::vector<double>& t, const std::vector<double>& y, const PowerLawFitConfig& c) {
  if (!(c.t_begin > 0) || !(c.t_end > c.t_begin)) throw InvalidInput("--fit: needs 0 < start < stop");
  if (c.windows < 1) throw InvalidInput("--fit: at least one sub-window");
  const double width = c.windows == 1 ? c.t_end - c.t_begin : (c.t_end - c.t_begin) / 2;
  const double shift = c.windows == 1 ? 0 : (c.t_end - c.t_begin - width) / static_cast<double>(c.windows - 1);
  std::vector<double> slopes;
  for (std::size_t w = 0; w < c.windows; ++w) {
    const double a = c.t_begin + static_cast<double>(w) * shift, b = a + width;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    std::size_t m = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i] < a * (1 - 1e-12) || t[i] > b * (1 + 1e-12)) continue;
      if (!(y[i] > 0)) throw InvalidInput("--fit: non-positive value at t = " + std::to_string(t[i]));
      const double x = std::log(t[i]), z = std::log(y[i]);
      sx += x, sy += z, sxx += x * x, sxy += x * z, ++m;
    }
    if (m < 3) throw InvalidInput("--fit: fewer than 3 samples in a sub-window; use more --samples or a wider range");
    const double mm = static_cast<double>(m);
    slopes.push_back((mm * sxy - sx * sy) / (mm * sxx - sx * sx));
  }
  PowerLawFit f;
  for (double s : slopes) f.slope += s;
  f.slope /= static_cast<double>(slopes.size());
  for (double s : slopes) f.slope_error += (s - f.slope) * (s - f.slope);
  f.slope_error = slopes.size() > 1 ? std::sqrt(f.slope_error / static_cast<double>(slopes.size() - 1)) : 0.0;
  const double t_star = c.t_star < 0 ? c.t_begin : c.t_star;
  const auto ld = log_derivative(t, y);
  for (std::size_t i = 0; i < ld.size(); ++i)
    if (t[i + 1] >= t_star) f.max_deviation = std::max(f.max_deviation, std::abs(ld[i] - f.slope));
  f.power_law = f.max_deviation < c.kappa;
  return f;
}

}  // namespace granular
