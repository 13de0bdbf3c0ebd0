#pragma once
// Everything said about one exponent of one curve (docs/physics.md, "Nonlinear dynamics"): the fitted slope, the mean log
// derivative, whether the curve is a power law at all, and which of the two a table shows.
// The paper's rule: a power law shows its fitted slope; a curve "markedly different from a
// power law" is starred and shows "mean values of L_d(t) for t ∈ [4, 10] ms".
#include <limits>
#include <vector>

#include "granular/analysis/power_law_fit.hpp"

namespace granular {

struct ExponentReport {
  ExponentEstimate fit;      ///< least-squares slope: mean ± spread over the six sub-windows
  ExponentEstimate mean_ld;  ///< mean L_d over the window ± spread of its sub-window means
  PowerLawVerdict verdict;   ///< |L_d − fit| < κ after t*?
  /// Realization errors (bootstrap.hpp) of `fit` and `mean_ld`; NaN until an ensemble sets them.
  double fit_realization_error = std::numeric_limits<double>::quiet_NaN();
  double mean_ld_realization_error = std::numeric_limits<double>::quiet_NaN();

  bool starred() const { return !verdict.power_law; }
  /// What a table shows: the fit for a power law, the mean L_d (starred) otherwise.
  const ExponentEstimate& shown() const { return starred() ? mean_ld : fit; }
  double shown_realization_error() const { return starred() ? mean_ld_realization_error : fit_realization_error; }
};

/// Fit, mean L_d and verdict of y ∝ t^s on [lo, hi]. Throws InvalidInput when a sub-window holds
/// fewer than 2 samples.
ExponentReport report_exponent(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi,
                               const PowerLawCriterion& criterion);

}  // namespace granular
