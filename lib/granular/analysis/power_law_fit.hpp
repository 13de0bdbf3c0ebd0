#pragma once
// Power laws y ∝ t^s fitted by least squares in log–log, on a family of sub-windows of the fit
// interval, the mean log derivative over it, and the criterion that decides whether a curve is
// a power law at all (docs/physics.md, "Transport exponents").
//
// The sub-windows: [a, b] is cut into 4 equal parts at p0 = a < p1 < p2 < p3 < p4 = b (linear in
// t, as the paper's "4–10 ms"), and every run of at least two consecutive parts is one window:
// [p0,p2] [p1,p3] [p2,p4] [p0,p3] [p1,p4] [p0,p4]. The paper: "we fit for different intervals of
// time between 4×10⁻³ s and 10⁻² s, then we average the slopes and calculate the standard
// deviation". The exponent is the mean slope over these six windows and its error their standard
// deviation (sample, n−1): how much the answer depends on where one looks, not a statistical
// error over realizations (bootstrap.hpp gives that one).
//
// Window edges include samples within 1e-9 (relative) of them, so a sample at 4 ms computed as
// 4000 × 1e-6 s belongs to a window starting at 4e-3 s whichever way it rounded.
#include <vector>

namespace granular {

struct LineFit {
  double slope = 0, intercept = 0;  ///< ln y ≈ intercept + slope ln t
  std::size_t points = 0;
};

/// Least squares of ln y on ln t over samples with lo ≤ t ≤ hi and t, y > 0.
/// Throws InvalidInput if fewer than 2 points qualify.
LineFit fit_power_law(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi);

/// How many of the times t lie in [lo, hi] (edges as above).
std::size_t samples_inside(const std::vector<double>& t, double lo, double hi);

/// Least-squares slope of v against log10 t over the samples with lo ≤ t ≤ hi (edges as above;
/// every t > 0): how fast a logarithm such as ⟨log10 Λ⟩ grows per decade. NaN if a v there is
/// not finite. Throws InvalidInput if fewer than 2 samples (or a single distinct time) are inside.
double log_time_slope(const std::vector<double>& t, const std::vector<double>& v, double lo, double hi);

/// The exponent s of y ∝ t^s: log_time_slope of log10 y, NaN if a y inside is ≤ 0 (unlike
/// fit_power_law, which skips such samples, a curve that touches 0 in the window has no exponent).
double loglog_slope(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi);

struct ExponentEstimate {
  double value = 0;            ///< the estimate
  double error = 0;            ///< standard deviation over the six sub-windows
  std::vector<double> slopes;  ///< one per sub-window, in the order documented above
};

/// Exponent on the six sub-windows of [lo, hi] (each must hold at least 2 samples): value = the
/// mean of the six slopes.
ExponentEstimate windowed_exponent(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi);

/// Mean of the log derivative L_d = Δ ln y / Δ ln t over consecutive samples with both ends in
/// [lo, hi]. Throws InvalidInput if there is no such pair.
double mean_log_derivative(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi);

/// The paper's value for the cases it stars: "the reported exponents correspond to mean values of
/// L_d(t) for t ∈ [4, 10] ms". value = mean L_d over [lo, hi]; error and slopes: the mean L_d on
/// each of the six sub-windows and their standard deviation, as for the fitted exponent.
ExponentEstimate windowed_mean_log_derivative(const std::vector<double>& t, const std::vector<double>& y, double lo,
                                              double hi);

struct PowerLawCriterion {
  double kappa = 0.1;     ///< largest tolerated |L_d − γ|
  double t_start = 4e-3;  ///< t*: deviations before it are ignored [s]
};

struct PowerLawVerdict {
  bool power_law = false;  ///< |L_d(t) − γ| < κ for every sampled t ≥ t*
  double worst_deviation = 0;
  double worst_time = 0;  ///< where the worst deviation sits
};

/// Judges y ∝ t^γ by the log derivative on the sampled times (consecutive samples, no
/// smoothing: the paper computes L_d "where we discretize time as in our numerical
/// integration") after t*. No L_d sample after t* counts as not a power law.
PowerLawVerdict judge_power_law(const std::vector<double>& t, const std::vector<double>& y, double gamma,
                                const PowerLawCriterion& criterion);

}  // namespace granular
