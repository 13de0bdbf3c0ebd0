#pragma once
// Power-law exponents of a time series (SPEC §4 "Ensembles and exponents"): least-squares
// slopes of ln y against ln t on several sub-windows of [t_begin, t_end], their mean ± standard
// deviation, and the log derivative L_d to tell a power law from something that is not one.
#include <cstddef>
#include <vector>

namespace granular {

struct PowerLawFitConfig {
  double t_begin = 4e-3;    ///< fit range start [s]
  double t_end = 1e-2;      ///< fit range end [s]
  std::size_t windows = 4;  ///< sub-windows, each half the range wide, starts evenly spaced
  double kappa = 0.25;      ///< |L_d − slope| ≥ κ after t* means "not a power law"
  double t_star = -1;       ///< t* [s]; < 0: t_begin
};

struct PowerLawFit {
  double slope = 0;          ///< mean over sub-windows
  double slope_error = 0;    ///< standard deviation over sub-windows
  double max_deviation = 0;  ///< max |L_d(t) − slope| for t ≥ t*
  bool power_law = false;    ///< max_deviation < κ
};

/// Throws InvalidInput when a sub-window holds fewer than 3 samples or y ≤ 0 there.
PowerLawFit fit_power_law(const std::vector<double>& t, const std::vector<double>& y, const PowerLawFitConfig& config);

/// L_d on consecutive samples: Δ ln y / Δ ln t (size − 1 values, at the later time).
std::vector<double> log_derivative(const std::vector<double>& t, const std::vector<double>& y);

}  // namespace granular
