#pragma once
// The typed case of a kicked-chain run (docs/physics.md, "Transport exponents"): which chain, which
// kick where, how each realization is integrated and sampled, how many realizations, and the fit
// window — everything that determines the result, described as JSON and read back (describe,
// parse_case). Its schema is transport_parameters.hpp; the study that runs it, study/transport_study.hpp.
//
// Sampling: `dynamics.spread.samples` log-spaced times from τ to T for the curves, replaced inside the
// fit window by a uniform grid every `fit_step` (10 µs by default), where γ, η and L_d are taken.
// The mean m̃2 is taken about the excited bead (the paper's definition, the default) and about the
// energy centroid; both are fitted, both are reported.
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/analysis/bootstrap.hpp"
#include "granular/analysis/exponent_report.hpp"
#include "granular/case/mode_kick.hpp"
#include "granular/case/spreading_run.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/sampling.hpp"
#include "granular/model/chain_recipe.hpp"
#include "granular/model/disorder.hpp"
#include "granular/model/material.hpp"

namespace granular {

/// A single-site displacement or velocity kick, or a linear mode of the chain (study/mode_kick.hpp).
enum class Kick { displacement, velocity, mode };
Kick parse_kick(const std::string& name);
std::string to_string(Kick kick);

/// The paper's velocity kick for every F0: "β = 8·10⁻³ m/s" (docs/physics.md, "Nonlinear dynamics"; one place in its
/// text says 8e-1, a typo). It is the energy-matched β of α = 1e-7 m on the homogeneous chain at 10 N.
inline constexpr double paper_beta = 8e-3;

struct TransportCase {
  /// Which chain realization r is (N = 2501 beads, F0 = 10 N, the paper's two types by default).
  ChainRecipe chain{.N = 2501};
  Kick kick = Kick::displacement;
  double alpha = 1e-7;  ///< displacement kick [m] (also what a matched β matches)
  /// Velocity kick [m/s]; none: the velocity carrying the energy of α on each chain ("match").
  std::optional<double> beta = paper_beta;
  ModeKick mode;  ///< mode kick: which mode and its energy (or amplitude: α)
  /// The kicked bead n0 counting from 1 (1 … N); 0: the centre, (N+1)/2. kicked_bead() is its index.
  std::size_t site = 0;
  SpreadCentre centre = SpreadCentre::site;  ///< which m̃2 the tables show (both are computed)
  SpreadingRunConfig dynamics;               ///< T, τ, integrator, force law, samples, guards, observers
  /// What settling the case (case_settling.hpp) resolves: the time step τ [s] the user gave (none:
  /// the stability rule's default, from the preferred dynamics.integration.time_step, the paper's
  /// 1 µs) and whether the scheme is chosen with it (the integrator "auto": until settled the case
  /// stands for SABA2C). A settled case, and one read back by parse_case, has τ given and no
  /// automatic scheme.
  std::optional<double> time_step;
  bool automatic_integrator = false;
  std::size_t realizations = 500;
  std::size_t profile_realizations =
      std::numeric_limits<std::size_t>::max();  ///< E_n(T) averaged over the first this many (0: none)
  bool fit = true;                              ///< fit γ and η (needs fit_end ≤ T)
  double fit_begin = 4e-3, fit_end = 1e-2;      ///< exponents fitted on [fit_begin, fit_end] s
  double fit_step = DenseGrid{}.step;           ///< spacing of the samples inside the fit window [s]
  PowerLawCriterion criterion;                  ///< κ and t* of the power-law check
  BootstrapConfig bootstrap;                    ///< realization errors (threads: those of the run)
};

/// The 0-based index of the bead c.site names in c.chain (the centre (N−1)/2 for site 0).
std::size_t kicked_bead(const TransportCase& c);

/// Throws InvalidInput (naming the option) on an impossible case, before any work.
void validate(const TransportCase& c);
/// The checks of validate() that do not judge anything on the grid of time steps: the chain, the
/// kick, T and τ each finite and > 0, the fit window against T. What the stability limit of τ
/// needs (time_step_rule.hpp), so that a τ past it can be named before a fit_step or a T that
/// is no whole number of such steps (validate_and_settle, scheme_choice.hpp).
void validate_before_time_step(const TransportCase& c);

/// Refuses a Lyapunov spectrum or covariant vectors in a run of an ensemble, even of one
/// realization: they are one realization's, and an ensemble neither averages nor records them.
/// Throws InvalidInput naming `lyapunov_vectors` or `covariant_vectors`.
void refuse_spectrum_in_ensemble(const SpreadingRunConfig& run);

/// Every parameter that determines the result, as JSON (the checkpoint's identity, the run's
/// "parameters", Python's metadata, the case file that replays a failed realization): one key per
/// row of case_parameters() under the row's name (`alpha`, `time_step`, `ic`, …; units in the
/// rows' help), the chain's fields (describe_fields) and `profile_realizations`.
nlohmann::json describe(const TransportCase& c);
/// The inverse of describe: parse_case(describe(c)) describes as c does (c.fit follows from the
/// window and T: fit_within_duration). Throws InvalidInput naming a key that is missing or of the
/// wrong kind, and saying so of a case of granular 0.2.0 (keys with units: dt_s, alpha_m, …).
TransportCase parse_case(const nlohmann::json& described);

/// The spreading run of one realization of `c`: its dynamics with the kicked site and the dense
/// grid of the fit window.
SpreadingRunConfig spreading_config(const TransportCase& c);

struct KickedChain {
  State initial;
  double beta = 0;      ///< the velocity kick used [m/s] (the matched one when β is none); 0 for a displacement
  ModeKickResult mode;  ///< mode kick: the mode used (number, frequency, IPR, amplitude, energy); else empty
};
/// The kick of `c` applied to `chain` at c.site (a mode kick: the mode c.mode of `chain`, with the
/// amplitude α unless c.mode.energy is set; m̃2 is still taken about c.site).
KickedChain kick(const TransportCase& c, const Chain& chain);

}  // namespace granular
