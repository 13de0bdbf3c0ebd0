#pragma once
// The parameters of a kicked-chain run, described over the typed TransportCase itself: each row
// of transport_parameters() reaches its field of the case (c.alpha, c.dynamics.integration.duration,
// …), so the `spreading` and `exponents` tools bind their flags and granular.spreading, transport
// and exponent_table their keywords straight to the case, with the case's own defaults (the
// paper's: α = 1e-7 m, β = 8e-3 m/s, the centre bead, m̃2 about the kicked site, fits on 4–10 ms
// every 10 µs, t* = 4 ms, κ = 0.1), and validate(TransportCase) checks them. Errors name the
// parameter (`site`, `window_threshold`, `fit`); each front end tells it in its own words.
#include <vector>

#include "granular/case/transport_case.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

/// Each parameter of a kicked run: meaning, units, where it lives in the case, how a command line
/// writes it (`beta` a velocity or 'match', `fit` start:stop, `active_window` on|off, the enums as
/// words) and which choice it takes effect with (`energy_guard`: `max_energy_error`). Beyond the
/// paper (docs/physics.md, "Nonlinear dynamics"): dissipation and the tangent map.
const ParameterTable<TransportCase>& transport_parameters();

/// The rows a kicked case takes beyond transport_parameters(): the kick `ic` (displacement,
/// velocity or mode: the mode of `run.mode`, mode_kick_parameters()) and the `realizations`
/// averaged (>= 1), each reaching its field of TransportCase.
const ParameterTable<TransportCase>& kicked_case_parameters();

/// Every row of a kicked case, the rows its JSON is made of (describe, parse_case): the kick and
/// the realizations, transport_parameters(), and the mode kick's own (mode_kick_parameters(),
/// reaching TransportCase::mode).
const ParameterTable<TransportCase>& case_parameters();

/// The fields of a mode kick a front end sets (not `amplitude`: a run's `alpha` gives it).
const ParameterTable<ModeKick>& mode_kick_parameters();

/// Whether any of a mode kick's own fields (mode, near_khz, energy) is set: what only a mode kick
/// may use.
inline bool chosen(const ModeKick& kick) { return kick.mode != 0 || kick.near_khz || kick.energy != 0; }

/// Only a mode kick may use a ModeKick's fields: throws InvalidInput naming them if `kick` is
/// chosen and `kicks` (the kicks the case runs: an exponent table runs several) lacks Kick::mode.
void refuse_mode_without_mode_kick(const ModeKick& kick, const std::vector<Kick>& kicks);

/// Sets c.fit: whether the fit window ends by T (1e-12 relative slack). A single run or an
/// ensemble whose window ends past T gives no exponents, only a note (the exponent table refuses
/// such a window instead: validate).
void fit_within_duration(TransportCase& c);

}  // namespace granular
