#include "granular/analysis/box_counting.hpp"

#include <algorithm>
#include <cmath>

#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {

std::vector<double> geometric_box_sizes(double largest, double smallest, std::size_t count) {
  if (!(smallest > 0) || !(largest > smallest) || !std::isfinite(largest) || count < 2)
    throw InvalidInput("box_sizes", " " + format_number(largest) + " to " + format_number(smallest) +
                                        ": need 0 < smallest < largest and at least 2 sizes");
  std::vector<double> sizes(count);
  for (std::size_t i = 0; i < count; ++i)
    sizes[i] = largest * std::pow(smallest / largest, static_cast<double>(i) / static_cast<double>(count - 1));
  return sizes;
}

BoxCountingDimension box_counting_dimension(std::span<const double> points, const std::vector<double>& box_sizes) {
  if (points.empty()) throw InvalidInput("points", ": no points to cover");
  if (box_sizes.size() < 2) throw InvalidInput("box_sizes", ": a slope needs at least 2 box sizes");
  std::vector<double> sorted(points.begin(), points.end());
  for (double x : sorted)
    if (!std::isfinite(x)) throw InvalidInput("points", " " + format_number(x) + ": must be finite");
  std::sort(sorted.begin(), sorted.end());
  BoxCountingDimension out;
  out.box_sizes = box_sizes;
  std::vector<double> x, y;
  for (double eps : box_sizes) {
    if (!(eps > 0) || !std::isfinite(eps))
      throw InvalidInput("box_sizes", " " + format_number(eps) + ": must be finite and > 0");
    // Sorted points: a new box starts whenever a point leaves the current one.
    std::size_t boxes = 0;
    double current = -1;
    for (double p : sorted)
      if (const double box = std::floor((p - sorted.front()) / eps); box != current) ++boxes, current = box;
    out.counts.push_back(boxes);
    x.push_back(std::log(1 / eps));
    y.push_back(std::log(static_cast<double>(boxes)));
  }
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / n, my += y[i] / n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
  if (!(sxx > 0)) throw InvalidInput("box_sizes", ": need at least 2 different sizes");
  out.dimension = sxy / sxx;
  if (x.size() > 2) {
    double residuals = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double r = y[i] - my - out.dimension * (x[i] - mx);
      residuals += r * r;
    }
    out.error = std::sqrt(residuals / (n - 2) / sxx);
  }
  return out;
}

}  // namespace granular
