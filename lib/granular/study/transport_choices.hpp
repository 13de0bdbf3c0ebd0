#pragma once
// The choices of a kicked-chain run as front ends take them — the `spreading` and `exponents`
// tools' dynamics options, the Python keywords of granular.spreading, transport and
// exponent_table — turned into a TransportCase by one rule, so that the same words give the same
// case everywhere. Defaults are the paper's (α = 1e-7 m, β = 8e-3 m/s, the centre bead, m̃2 about
// the kicked site, fits on 4–10 ms every 10 µs, t* = 4 ms, κ = 0.1). Errors name the choice
// (`site`, `window_threshold`, `fit`); each front end tells it in its own words.
#include <optional>
#include <string>

#include "granular/parameter_table.hpp"
#include "granular/study/transport_study.hpp"

namespace granular {

struct TransportChoices {
  double alpha = 1e-7;                      ///< displacement kick [m] (also what a matched β matches)
  std::optional<double> beta = paper_beta;  ///< velocity kick [m/s]; none: β matching α's energy on each chain
  long long site = 0;                       ///< kicked bead 1…N (counting from 1); 0: the centre (N+1)/2
  std::string centre = "site";              ///< site | centroid: the m̃2 the tables show
  double duration = 1e-2;                   ///< T [s]
  std::optional<double> time_step;          ///< τ [s]; none: the stability rule's (TransportCase::time_step)
  std::string integrator = "saba2c";        ///< saba2c | saba2 | aba864 | srkn14a | reference | auto
  std::string force_law = "hertz";          ///< hertz | fpu | linear
  long long samples = 100;                  ///< sample times outside the fit window (≥ 2)
  std::string sampling = "log";             ///< log | uniform
  double fit_begin = 4e-3, fit_end = 1e-2;  ///< fit window [s], 0 < begin < end
  double fit_step = 1e-5;                   ///< sample spacing inside it [s]
  double t_star = 4e-3, kappa = 0.1;        ///< the power-law criterion
  long long bootstrap = 1000;               ///< resamples of the realization bootstrap (≥ 2)
  bool active_window = true;
  double window_threshold = 1e-30;      ///< finite, ≥ 0
  double reference_max_step = 0.01e-6;  ///< [s], finite, ≥ 0; 0 = none
  double max_energy_error = 1e-3;       ///< finite, ≥ 0; 0 = unwatched
  std::string energy_guard = "stop";    ///< stop | warn
};

/// Each choice's meaning and units (parameter_table.hpp): what front ends make their options,
/// attributes and help of. `fit` is the window [fit_begin, fit_end] in a front end's own form.
const ParameterTable<TransportChoices>& transport_parameters();

/// Fills `c` from the choices: everything but the chain (disorder, q, ξ, N, F0, R1, seed,
/// realizations) and the kick kind. Needs c.chain (its size, for `site`). Leaves c.fit true. What
/// settling resolves goes into the case: c.time_step (none unless `time_step` is given) and
/// c.automatic_integrator (integrator "auto", the case standing for SABA2C until settled).
/// Throws InvalidInput naming the choice.
void apply(const TransportChoices& choices, TransportCase& c);

/// Whether any of a mode kick's own fields (mode, near_khz, energy) is set: what only a mode kick
/// may use.
inline bool chosen(const ModeKick& kick) { return kick.mode != 0 || kick.near_khz >= 0 || kick.energy != 0; }

/// Sets c.mode to `kick`. Only a mode kick may use its fields: throws InvalidInput naming them
/// unless `kicks` (the kicks the case runs: an exponent table runs several) holds Kick::mode.
void apply(const ModeKick& kick, const std::vector<Kick>& kicks, TransportCase& c);

/// Sets c.fit: whether the fit window ends by T (1e-12 relative slack). A single run or an
/// ensemble whose window ends past T gives no exponents, only a note (the exponent table refuses
/// such a window instead: validate).
void fit_within_duration(TransportCase& c);

/// The choices beyond the paper (docs/physics.md, "Nonlinear dynamics"): dissipation and the
/// tangent map, each named as the parameter a front end reads it from (a tool's flag or a Python
/// keyword of that name).
struct BeyondChoices {
  double damping_time = 0, kk_gamma = 0;  ///< τ_d, γ_KK [s]; 0 = none
  bool mle = false;                       ///< the tangent map (X1(t))
  long long renormalize = 10;             ///< steps between renormalizations (≥ 1)
  long long deviation_samples = 0;  ///< times of the deviation vector's distribution (0 = none, else ≥ 2; needs mle)
};

/// Each choice's meaning and units, as transport_parameters.
const ParameterTable<BeyondChoices>& beyond_parameters();

/// The fields of a mode kick a front end sets (not `amplitude`: a run's `alpha` gives it).
const ParameterTable<ModeKick>& mode_kick_parameters();

/// Sets d.integration.damping, d.integration.lyapunov and d.deviation_samples. Throws InvalidInput naming the choice
/// (`damping_time`, `kk_gamma`, `renormalize`, `deviation_samples`).
void apply(const BeyondChoices& choices, SpreadingRunConfig& d);

/// apply(choices, c) and apply(beyond, c.dynamics).
void apply(const TransportChoices& choices, const BeyondChoices& beyond, TransportCase& c);

/// The choices that give `d`'s damping and tangent map (the inverse of apply).
BeyondChoices beyond_choices_of(const SpreadingRunConfig& d);

}  // namespace granular
