#pragma once
// The box-counting (Minkowski–Bouligand) dimension of a set of points on a line, such as the
// frequencies of a spectrum (docs/physics.md, "Quasiperiodic chains"): cover the points with a
// grid of boxes of size ε starting at the smallest point, count the boxes N(ε) that hold a point,
// and fit ln N(ε) = D ln(1/ε) + c by least squares over a range of ε. A finite sample of a fractal
// is only fractal between its extent and its smallest spacing, so the range matters and is
// reported with the slope; `error` is the slope's standard error from the fit's residuals, which
// says how straight the log–log line is over that range (not a bound on the true dimension).
//
//   auto sizes = granular::geometric_box_sizes(0.5 * extent, 0.01 * extent, 12);
//   auto d = granular::box_counting_dimension(frequencies, sizes);   // d.dimension ± d.error
#include <cstddef>
#include <span>
#include <vector>

namespace granular {

struct BoxCountingDimension {
  double dimension = 0;             ///< D, the fitted slope
  double error = 0;                 ///< standard error of D (0 with two sizes)
  std::vector<double> box_sizes;    ///< ε, largest first (the fitting range: front() … back())
  std::vector<std::size_t> counts;  ///< N(ε), one per size
};

/// `count` sizes from `largest` down to `smallest`, evenly spaced in ln ε. Throws InvalidInput
/// ("box_sizes") unless 0 < smallest < largest (finite) and count ≥ 2.
std::vector<double> geometric_box_sizes(double largest, double smallest, std::size_t count);

/// N(ε) of the points for each box size, and D fitted over all of them. Throws InvalidInput
/// ("points", "box_sizes") on no points, non-finite points, fewer than 2 sizes or a size ≤ 0.
BoxCountingDimension box_counting_dimension(std::span<const double> points, const std::vector<double>& box_sizes);

}  // namespace granular
