#pragma once
// The integrator "auto": the cheapest scheme and step that keep the energy error at the level of
// SABA2C at τ = 1 µs, from the cost–accuracy table of docs/performance.md, "Dynamics" (Hertz, F0 =
// 10 N, window off). There SRKN14a costs 4.0× a SABA2C step; at τ = 4 µs it matches SABA2C at
// 1 µs in cost with a 600× smaller energy error, at 8 µs it costs half with 1.3× SABA2C's error.
// 8 µs does not divide the 10 µs grid of the fit window, so the choice is SRKN14a at 5 µs
// (energy error ≈ 4e-8 by the measured τ^9.7 between 4 and 8 µs; 0.80× SABA2C's cost). Its
// accuracy was measured at ω_max·τ = 1.47 (ω_max = 2.9355e5 rad/s of the benchmark chain by
// time_step_rule.hpp), so a stiffer chain gets 5 µs/k, the smallest k keeping ω_max·τ ≤ 1.47 (far
// inside SRKN14a's stability limit h*); the choice stays SRKN14a only while it is cheaper than
// SABA2C at its own default step (whose margin, τ ≤ τ_max/6, was set by the same accuracy).
// A high order needs a smooth force: where a Hertzian contact can open (F0 = 0, or a kick whose
// energy can stretch a bond past its static overlap) the force's derivatives jump and SRKN14a at
// 5 µs was measured 1.1–8× *worse* than SABA2C at 1 µs (docs/beyond-the-paper.md, "Long times"),
// so there the choice is SABA2C.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/case/transport_case.hpp"

namespace granular {

struct SchemeChoice {
  std::string integrator;         ///< "srkn14a" or "saba2c"
  double time_step = 0;           ///< its default τ [s] (before the stability rule's own check)
  double relative_cost = 1;       ///< CPU per simulated second relative to SABA2C at its default τ
  bool bonds_stay_closed = true;  ///< no contact can open (the force stays smooth)
  bool damped = false;            ///< damping on: SABA2C at its rule step (a damped step is 2nd order anyway)
};

/// True when no bond of any chain of case `c` can open: the force law is not Hertz, or the kick's
/// largest energy H0 (kick_energy_bound over rule_chains, time_step_rule.hpp: the case's own chain
/// when its recipe gives one, else any arrangement of the radii it draws; a mode kick by its real
/// mode or its bound) is below the smallest energy φ_k(−δ_k) that stretches a bond (walls
/// included) from its static overlap δ_k to zero; as every φ_k ≥ 0 and they sum with the kinetic
/// energy to H0, no φ_k can reach it. `chain`: as time_step_limit.
bool bonds_stay_closed(const TransportCase& c, const Chain* chain = nullptr);

/// SRKN14a's step cost in SABA2C steps (docs/performance.md, "Dynamics": 72.2 ms at 4 µs vs 72.0 ms at 1 µs).
inline constexpr double srkn14a_step_cost = 4.0;
/// SRKN14a's preferred step: the largest divisor of the 10 µs fit grid within the measured 8 µs.
inline constexpr double srkn14a_preferred_step = 5e-6;

/// ω_max·τ of the benchmark run whose accuracy SRKN14a's preferred step reproduces.
inline constexpr double srkn14a_accurate_omega_tau = 2.9355e5 * srkn14a_preferred_step;

/// SRKN14a's default step on chains of highest frequency `omega_max` [rad/s]: 5 µs/k, k the
/// smallest integer with ω_max·τ ≤ srkn14a_accurate_omega_tau.
double srkn14a_default_step(double omega_max);

/// The choice given the default steps each scheme gets (SABA2C's from time_step_rule.hpp, 1 µs or
/// 1 µs/k; SRKN14a's from srkn14a_default_step).
/// With damping on, SABA2C: the damping flow is composed with any scheme by a 2nd-order Strang
/// splitting, whose error at SRKN14a's 5 µs is ~25× that at SABA2C's 1 µs.
SchemeChoice choose_scheme(double saba2c_step, double srkn14a_step, bool closed, bool damped = false);

/// The choice and why, for the JSON.
nlohmann::json to_json(const SchemeChoice& choice);

/// The time step of a study's cases (settle_time_step, time_step_rule.hpp), and when they ask for
/// an automatic scheme (TransportCase::automatic_integrator, the integrator word "auto") the scheme
/// first: SABA2C's default step by the stability rule, then choose_scheme over every case (one
/// scheme and step for all), then the stability check of what was chosen. The returned rule is
/// settle_time_step's, with "integrator_choice" when automatic. An automatic choice with a given
/// time step is an InvalidInput naming "dt": the choice sets the step. The cases leave settled.
/// `chain`: as settle_time_step (this very chain rather than every realization of the cases'
/// distribution).
nlohmann::json settle_scheme_and_step(std::vector<TransportCase>& cases, const Chain* chain = nullptr);
/// The same for one case.
nlohmann::json settle_scheme_and_step(TransportCase& c, const Chain* chain = nullptr);

}  // namespace granular
