#pragma once
// `--integrator auto`: the cheapest scheme and step that keep the energy error at the level of
// SABA2C at τ = 1 µs, from the cost–accuracy table of docs/dynamics-performance.md (Hertz, F0 =
// 10 N, window off). There SRKN14a costs 4.0× a SABA2C step; at τ = 4 µs it matches SABA2C at
// 1 µs in cost with a 600× smaller energy error, at 8 µs it costs half with 1.3× SABA2C's error.
// 8 µs does not divide the 10 µs grid of the fit window, so the choice is SRKN14a at 5 µs
// (energy error ≈ 4e-8 by the measured τ^9.7 between 4 and 8 µs; 0.80× SABA2C's cost), made
// smaller by the stability rule like any default step, and kept only while it is cheaper than
// SABA2C at its own default step.
#include <string>

#include <nlohmann/json.hpp>

namespace granular {

struct SchemeChoice {
  std::string integrator;  ///< "srkn14a" or "saba2c"
  double time_step = 0;    ///< its default τ [s] (before the stability rule's own check)
  double relative_cost = 1;  ///< CPU per simulated second relative to SABA2C at its default τ
};

/// SRKN14a's step cost in SABA2C steps (docs/dynamics-performance.md: 72.2 ms at 4 µs vs 72.0 ms at 1 µs).
inline constexpr double srkn14a_step_cost = 4.0;
/// SRKN14a's preferred step: the largest divisor of the 10 µs fit grid within the measured 8 µs.
inline constexpr double srkn14a_preferred_step = 5e-6;

/// The choice given the default steps the stability rule leaves each scheme (τ_saba2c: SABA2C's
/// default, 1 µs or 1 µs/k; τ_srkn14a: SRKN14a's, 5 µs or 5 µs/k).
SchemeChoice choose_scheme(double saba2c_step, double srkn14a_step);

/// The choice and why, for the JSON.
nlohmann::json to_json(const SchemeChoice& choice);

}  // namespace granular
