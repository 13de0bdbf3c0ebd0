#pragma once
// Local exponent of a sampled curve: L_d = Δ ln y / Δ ln t (docs/physics.md, "Nonlinear dynamics"). Each sample is
// paired with the first later one at least `min_log_step` further in ln t (0: the next sample), so densely sampled,
// slightly noisy curves do not turn into noise when differentiated.
#include <vector>

namespace granular {

struct LogDerivative {
  std::vector<double> t;      ///< geometric midpoints sqrt(t_i t_j)
  std::vector<double> slope;  ///< (ln y_j − ln y_i) / (ln t_j − ln t_i)
};

/// Skips pairs with a non-positive t or y (no logarithm). Throws InvalidInput on size mismatch.
LogDerivative log_derivative(const std::vector<double>& t, const std::vector<double>& y, double min_log_step = 0);

}  // namespace granular
