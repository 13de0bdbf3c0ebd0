#include "granular/analysis/power_law_fit.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "granular/analysis/log_derivative.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

constexpr double edge_tolerance = 1e-9;

bool inside(double t, double lo, double hi) { return t >= lo * (1 - edge_tolerance) && t <= hi * (1 + edge_tolerance); }

// p0 … p4: the fit interval cut into four equal parts; the six windows are runs of ≥ 2 parts.
constexpr int windows[6][2] = {{0, 2}, {1, 3}, {2, 4}, {0, 3}, {1, 4}, {0, 4}};

template <class Estimate>
ExponentEstimate over_sub_windows(double lo, double hi, const Estimate& estimate) {
  if (!(hi > lo && lo >= 0)) throw InvalidInput("fit interval must satisfy 0 <= start < stop");
  double p[5];
  for (int i = 0; i <= 4; ++i) p[i] = lo + (hi - lo) * i / 4.0;
  p[4] = hi;
  ExponentEstimate e;
  for (const auto& w : windows) e.slopes.push_back(estimate(p[w[0]], p[w[1]]));
  double mean = 0;
  for (double s : e.slopes) mean += s;
  mean /= static_cast<double>(e.slopes.size());
  double var = 0;
  for (double s : e.slopes) var += (s - mean) * (s - mean);
  e.value = mean;
  e.error = std::sqrt(var / static_cast<double>(e.slopes.size() - 1));
  return e;
}

// The least-squares line through the points (x_i, y_i), i < n, of the sums Σx, Σy, Σx², Σxy:
// the one home of the formula that fit_power_law and log_time_slope share.
struct LineSums {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  std::size_t n = 0;
  void add(double x, double v) {
    sx += x;
    sy += v;
    sxx += x * x;
    sxy += x * v;
    ++n;
  }
  LineFit line(double lo, double hi) const {
    if (n < 2)
      throw InvalidInput("fit window [" + std::to_string(lo) + ", " + std::to_string(hi) + "] holds " +
                         std::to_string(n) + " usable samples; need 2 (more samples or a wider fit interval)");
    const double nn = static_cast<double>(n);
    const double denominator = nn * sxx - sx * sx;
    if (!(denominator > 0)) throw InvalidInput("fit window has a single distinct time");
    LineFit f;
    f.slope = (nn * sxy - sx * sy) / denominator;
    f.intercept = (sy - f.slope * sx) / nn;
    f.points = n;
    return f;
  }
};

}  // namespace

LineFit fit_power_law(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi) {
  if (t.size() != y.size()) throw InvalidInput("fit_power_law: t and y differ in length");
  LineSums sums;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (inside(t[i], lo, hi) && t[i] > 0 && y[i] > 0) sums.add(std::log(t[i]), std::log(y[i]));
  return sums.line(lo, hi);
}

std::size_t samples_inside(const std::vector<double>& t, double lo, double hi) {
  std::size_t n = 0;
  for (const double x : t) n += inside(x, lo, hi) ? 1 : 0;
  return n;
}

double log_time_slope(const std::vector<double>& t, const std::vector<double>& v, double lo, double hi) {
  if (t.size() != v.size()) throw InvalidInput("log_time_slope: t and v differ in length");
  LineSums sums;
  bool finite = true;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (inside(t[i], lo, hi) && t[i] > 0) {
      finite = finite && std::isfinite(v[i]);
      sums.add(std::log10(t[i]), v[i]);
    }
  const LineFit f = sums.line(lo, hi);
  return finite ? f.slope : std::numeric_limits<double>::quiet_NaN();
}

double loglog_slope(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi) {
  std::vector<double> v(y.size());
  for (std::size_t i = 0; i < y.size(); ++i)
    v[i] = y[i] > 0 ? std::log10(y[i]) : std::numeric_limits<double>::quiet_NaN();
  return log_time_slope(t, v, lo, hi);
}

ExponentEstimate windowed_exponent(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi) {
  return over_sub_windows(lo, hi, [&](double a, double b) { return fit_power_law(t, y, a, b).slope; });
}

double mean_log_derivative(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi) {
  if (t.size() != y.size()) throw InvalidInput("mean_log_derivative: t and y differ in length");
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    if (!inside(t[i], lo, hi) || !inside(t[i + 1], lo, hi)) continue;
    if (!(t[i] > 0 && t[i + 1] > t[i] && y[i] > 0 && y[i + 1] > 0)) continue;
    sum += std::log(y[i + 1] / y[i]) / std::log(t[i + 1] / t[i]);
    ++n;
  }
  if (n == 0)
    throw InvalidInput("mean log derivative on [" + std::to_string(lo) + ", " + std::to_string(hi) +
                       "] s: no two consecutive samples inside");
  return sum / static_cast<double>(n);
}

ExponentEstimate windowed_mean_log_derivative(const std::vector<double>& t, const std::vector<double>& y, double lo,
                                              double hi) {
  ExponentEstimate e = over_sub_windows(lo, hi, [&](double a, double b) { return mean_log_derivative(t, y, a, b); });
  e.value = mean_log_derivative(t, y, lo, hi);  // the paper's number: the mean over the whole window
  return e;
}

PowerLawVerdict judge_power_law(const std::vector<double>& t, const std::vector<double>& y, double gamma,
                                const PowerLawCriterion& c) {
  const LogDerivative d = log_derivative(t, y);
  PowerLawVerdict v;
  bool any = false;
  for (std::size_t i = 0; i < d.t.size(); ++i) {
    if (d.t[i] < c.t_start) continue;
    any = true;
    const double dev = std::fabs(d.slope[i] - gamma);
    if (dev > v.worst_deviation) {
      v.worst_deviation = dev;
      v.worst_time = d.t[i];
    }
  }
  v.power_law = any && v.worst_deviation < c.kappa;
  return v;
}

}  // namespace granular
