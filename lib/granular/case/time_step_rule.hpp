#pragma once
// The time step of a kicked-chain run, from the chain's highest frequency (docs/physics.md,
// "Time step"). A splitting scheme integrates a harmonic mode of angular frequency ω stably only
// while ωτ stays below a constant h* of the scheme, found here from its coefficients (2 for the
// leapfrog; SABA2C's corrector changes it). The fastest mode a run can meet is bounded above by
// ω_max: every bond at the stiffest strain the kick's energy H0 can give it (each bond's excess
// energy φ_k(x) ≥ 0, and the φ_k and the kinetic energy sum to H0, so φ_k ≤ H0), the largest
// eigenvalue of M^{-1/2} K M^{-1/2} bounded by Gershgorin's row sums. For a random chain the bound
// holds for every realization: it takes the worst arrangement of the bead types the disorder can
// produce around any bead. The rule is τ ≤ τ_max = h*/ω_max.
#include <limits>
#include <optional>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/case/transport_case.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/dynamics/state.hpp"
#include "granular/model/chain.hpp"

namespace granular {

/// The trace of one step of `scheme` on ẍ = −ω²x at h = ωτ (the step is a 2×2 map of determinant
/// 1 on (x, v/ω): bounded while |trace| ≤ 2).
double step_trace(const SplittingScheme& scheme, double h);

/// h* of a scheme: the largest h such that its step is stable, |trace| ≤ 2, on all of (0, h].
/// Higher-order schemes have narrow unstable gaps beyond it and stable stretches between them;
/// h* stops at the first gap.
double stable_step_limit(const SplittingScheme& scheme);

/// An upper bound of the highest angular frequency [rad/s] of `chain` under `law` at any state of
/// energy `energy` [J] above the static one.
double highest_frequency_bound(const ForceLaw& law, const Chain& chain, double energy);

struct TimeStepLimit {
  double omega_max = 0;                                            ///< ω_max [rad/s] (of any integrator)
  double scheme_limit = 0;                                         ///< h* of the integrator
  double max_time_step = std::numeric_limits<double>::infinity();  ///< τ_max [s]; ∞ for the adaptive reference
};

/// The chains a rule over every realization of `c` tries: `chain` when given, the recipe's one
/// chain when it gives one (a types or radii file), else three beads between walls in every
/// arrangement of the radii the recipe can draw (every neighbourhood of a bead or a bond).
std::vector<Chain> rule_chains(const TransportCase& c, const Chain* chain = nullptr);

/// The largest energy H0 [J] above the static state that c's kick gives any of `chains` at any
/// site; with `whole_chain` (the chains are the run's very chain) at c.site only, a mode kick by
/// its real mode. A mode of a chain not yet drawn has its energy given, or bounded from α.
double kick_energy_bound(const TransportCase& c, const std::vector<Chain>& chains, bool whole_chain);

/// The limit of case `c`: of `chain` when given, of the recipe's chain when it gives one, else
/// of every realization.
TimeStepLimit time_step_limit(const TransportCase& c, const Chain* chain = nullptr);

/// The margin of the default τ below the stability limit: stable is not accurate (at ωτ near h*
/// SABA2C's energy error reaches percents), and at τ_max/6 the worst mode's ωτ ≈ 0.5 keeps the
/// error of the paper's runs (ωτ ≈ 0.3 at τ = 1 µs, ξ = q = 0.5, F0 = 10 N).
inline constexpr double default_step_margin = 6;

/// The default τ: `preferred` (the paper's 1 µs) when it is within τ_max/default_step_margin, else
/// preferred/k with k the smallest integer that is. Every time that is a multiple of `preferred`
/// stays a whole number of steps.
double default_time_step(const TimeStepLimit& limit, double preferred = 1e-6);

/// Throws InvalidInput naming `time_step` when c's τ is past the limit, with the largest stable τ.
void check_time_step(const TransportCase& c, const TimeStepLimit& limit);

/// The rule and its numbers, for the JSON.
nlohmann::json to_json(const TimeStepLimit& limit);

/// Settles the time step of `cases` (validated) by the rule: a τ the user gave (the case's
/// `time_step`) past the limit of any case is refused (InvalidInput naming `time_step` and the
/// largest stable τ); a case without one gets default_time_step() of the tightest limit, from its
/// preferred dynamics.integration.time_step (the paper's 1 µs): one τ for all of them. Each case
/// leaves settled, its τ given. `chain`: the chain of a single case from a file (else every
/// realization counts). Returns the rule and its numbers for the JSON ("time_step_rule"), as the
/// tools and Python write it.
nlohmann::json settle_time_step(std::vector<TransportCase>& cases, const Chain* chain = nullptr);
/// The same for one case.
nlohmann::json settle_time_step(TransportCase& c, const Chain* chain = nullptr);

}  // namespace granular
