#pragma once
// The chain length of a long run (docs/physics.md, "Chain length for long times"): N large enough
// that no wave from the kicked centre bead reaches a wall by T. Energy cannot move faster than a
// speed Ω [beads/s] bounded by the chain's highest frequency: a harmonic chain of stiffness K and
// mass m carries signals at most at its sound speed √(K/m) = ω_top/2 beads/s (the group velocity
// dω/dk = √(K/m)·cos(k/2) of ω = 2√(K/m)·sin(k/2)), and ω_max of time_step_rule.hpp bounds ω_top
// for every bond at the stiffest strain the kick's energy H0 can give it. That bound also covers
// the sonic vacuum (F0 = 0), which has no linear sound speed: a pulse of energy ≤ H0 compresses
// no bond past φ_k = H0, so no bond is stiffer than there, and a nonlinear pulse is no faster
// than the linear sound speed at its peak strain (checked in tests/case/chain_length_rule_test).
// So v = ω_max/2 [beads/s] bounds the fastest group velocity, and N = 2⌈safety·v T⌉ + 1 + 2·pad
// beads: the safety factor covers the exponentially small precursor ahead of the front (the
// active window follows energy down to 1e-30 H0, which the test measures at ≤ 0.7 v).
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/case/chain_choices.hpp"
#include "granular/case/transport_case.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

struct ChainLength {
  double omega_max = 0;           ///< ω_max [rad/s] of time_step_rule.hpp (any integrator)
  double max_group_velocity = 0;  ///< v = ω_max/2 [beads/s]: no wave is faster
  double reach = 0;               ///< v T [beads]: farthest a wave can travel by T
  double safety = 1.1;            ///< factor on the reach
  std::size_t pad = 50;           ///< beads added on each side beyond it
  std::size_t n = 0;              ///< the chain length: 2⌈safety v T⌉ + 1 + 2 pad
};

/// The automatic N of case `c` (its chain kind, F0, kick, force law and T; not its N or τ).
ChainLength automatic_chain_length(const TransportCase& c);

/// Sizes `c` for long times: N = automatic_chain_length(c).n, the kick at the centre bead
/// ((N − 1)/2, 0-based), the chain drawn outward from it (centred_configuration.hpp), so that a
/// longer N only adds beads the wave never reaches. Returns the rule that gave N.
ChainLength size_for_long_times(TransportCase& c);

/// Sizing for long times kicks the centre bead: throws InvalidInput naming `site` unless `site`
/// (1..N, 0 = the centre) is 0.
void require_centre_kick(long long site);

/// The rules that sized `cases` (exponent_cases with automatic_length), one per case, for the
/// JSON; null unless `automatic`. `site`: the kicked bead asked for (require_centre_kick).
nlohmann::json length_rules(const std::vector<TransportCase>& cases, bool automatic, long long site);

/// A warning when waves from the kick could travel ten times the distance from the kicked bead
/// to the nearer wall of the case's chain by T (v T > 10 × that distance, v = omega_max/2 as
/// above, omega_max [rad/s] the time-step rule's TimeStepLimit::omega_max of the case, computed
/// once when its step is settled): a duration typed in milliseconds as seconds, most likely.
/// `option` names T as the user typed it ("--T", "T"); "" when T is plausible.
std::string duration_warning(const TransportCase& c, double omega_max, const std::string& option);

/// chain_parameters() whose `N` also reads 'auto' (ChainChoices::auto_n, N 3 until the front end
/// sizes it by this rule), for the front ends of long kicked runs.
const ParameterTable<ChainChoices>& long_run_chain_parameters();

/// The rule and its numbers, for the JSON.
nlohmann::json to_json(const ChainLength& length);

}  // namespace granular
