#pragma once
// Power laws y ∝ t^s fitted by least squares in log–log, on a family of sub-windows of the fit
// interval, and the criterion that decides whether a curve is a power law at all (SPEC §4).
//
// The sub-windows: [a, b] is cut into 4 equal parts at p0 = a < p1 < p2 < p3 < p4 = b (linear in
// t, as the paper's "4–10 ms"), and every run of at least two consecutive parts is one window:
// [p0,p2] [p1,p3] [p2,p4] [p0,p3] [p1,p4] [p0,p4]. The exponent is the mean slope over these six
// windows and its error their standard deviation (sample, n−1): how much the answer depends on
// where one looks, not a statistical error of one fit.
#include <vector>

namespace granular {

struct LineFit {
  double slope = 0, intercept = 0;  ///< ln y ≈ intercept + slope ln t
  std::size_t points = 0;
};

/// Least squares of ln y on ln t over samples with lo ≤ t ≤ hi and t, y > 0.
/// Throws InvalidInput if fewer than 2 points qualify.
LineFit fit_power_law(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi);

struct ExponentEstimate {
  double value = 0;             ///< mean slope over the sub-windows
  double error = 0;             ///< standard deviation of the slopes
  std::vector<double> slopes;   ///< one per sub-window, in the order documented above
};

/// Exponent on the six sub-windows of [lo, hi] (each must hold at least 2 samples).
ExponentEstimate windowed_exponent(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi);

struct PowerLawCriterion {
  double kappa = 0.1;        ///< largest tolerated |L_d − γ|
  double t_start = 4e-3;     ///< t*: deviations before it are ignored [s]
  double log_step = 0.1;     ///< L_d is taken over steps of at least 0.1 in ln t (≈ 10 % in t)
};

struct PowerLawVerdict {
  bool power_law = false;    ///< |L_d(t) − γ| < κ for every sampled t ≥ t*
  double worst_deviation = 0;
  double worst_time = 0;     ///< where the worst deviation sits
};

/// Judges y ∝ t^γ by the log derivative after t*. No L_d sample after t* counts as not a power law.
PowerLawVerdict judge_power_law(const std::vector<double>& t, const std::vector<double>& y, double gamma,
                                const PowerLawCriterion& criterion);

/// Both at once: the windowed exponent on [lo, hi] and the verdict on it.
struct PowerLawAnalysis {
  ExponentEstimate exponent;
  PowerLawVerdict verdict;
};
PowerLawAnalysis analyze_power_law(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi,
                                   const PowerLawCriterion& criterion);

}  // namespace granular
