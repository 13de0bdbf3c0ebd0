#pragma once
// The paper's whole protocol (docs/physics.md, "Nonlinear dynamics"): transport exponents γ (m̃2 ∝ t^γ) and η (P⁻¹ ∝ t^−η)
// for every chain kind × precompression × kick, each an ensemble (transport_study.hpp).
// Homogeneous chains are deterministic, so they run one realization whatever R is. Chains beyond
// the paper's kinds (k bead types, polydisperse radii, a quasiperiodic chain) join the study by name.
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "granular/ensemble/run_options.hpp"
#include "granular/model/quasiperiodic.hpp"
#include "granular/study/transport_study.hpp"

namespace granular {

/// A chain of the study drawn from a bead distribution (k types or polydisperse radii), or a
/// quasiperiodic chain (realization r takes the phase of (seed, r) unless one is given: an
/// ensemble over φ), under its own name: the `disorder` column of the outputs and the column of
/// the tables.
struct BeadChain {
  std::string name;
  BeadDistribution beads;
  std::optional<Quasiperiodic> quasi{};  ///< given: this chain instead of `beads`
};

struct ExponentTableConfig {
  std::vector<Disorder> chains{Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2};
  std::vector<BeadChain> bead_chains;  ///< after `chains`, with R realizations each (ξ, q, R1 unused)
  std::vector<double> precompressions{10, 0.5, 0.1, 0.01, 0};  ///< F0 [N]
  std::vector<Kick> kicks{Kick::displacement, Kick::velocity};
  TransportCase base;                                       ///< everything else (N, T, τ, ξ, q, R, seed, …)
  std::vector<double> profile_precompressions{10, 0.1, 0};  ///< F0s whose E_n(T) is averaged
  std::size_t profile_realizations = 100;                   ///< the paper averages profiles over 100
  bool automatic_length = false;  ///< each case's N from its T (chain_length_rule.hpp), drawn from the kicked centre
};

struct ExponentCell {
  TransportCase definition;
  TransportSummary summary;
  std::string chain{};  ///< its chain's name; empty: the name of definition.disorder
};

/// The chains' names in table order: `chains` (h, A, RDM1, RDM2), then the bead chains'.
std::vector<std::string> chain_names(const ExponentTableConfig& config);

/// The name of a cell's chain (ExponentCell::chain, else its disorder's).
std::string chain_name(const ExponentCell& cell);

/// Throws InvalidInput naming `chains` for no chain at all, `ic` for no kick, `mode` (and the mode
/// kick's other fields) chosen without the mode kick, `realizations` below 1, `chain_name` for a
/// bead chain's name that is empty, not CSV-safe or taken (by a disorder kind or another bead
/// chain), or the field of a bad distribution.
void validate(const ExponentTableConfig& config);

/// The checkpoint logs of a study's first `cases` cases: case i logs to `prefix`.<i>.
std::vector<std::string> case_checkpoints(const std::string& prefix, std::size_t cases);

/// The cases in table order (kick-major, then F0, then chain as chain_names gives them); with
/// automatic_length each sized (N, the centre kick, the centred draw) by automatic_chain_length.
std::vector<TransportCase> exponent_cases(const ExponentTableConfig& config);

/// Every case's realizations: the total of the progress meter run_exponent_table advances.
std::size_t total_realizations(const std::vector<TransportCase>& cases);

/// Runs every case of `cases`, exponent_cases(config) as settled (validate_and_settle: each
/// with its time step, scheme and kicked bead); under mpirun only rank 0 gets filled summaries. Memory: one case's
/// records at a time (transport_study.hpp), then its summary. `options.checkpoint` is the prefix
/// of the cases' logs (case i logs to <prefix>.<i>; empty: no checkpoints), `options.progress`
/// (optional) counts every case's realizations (total_realizations).
std::vector<ExponentCell> run_exponent_table(const ExponentTableConfig& config, const std::vector<TransportCase>& cases,
                                             const RunOptions& options);

/// One table cell: "1.763 ± 0.012 (± 0.020 real.)", the shown value ± its sub-window spread and
/// (when an ensemble gave one) its realization error; a trailing * marks a starred cell (not a
/// power law: the value is the mean L_d over the fit window).
std::string cell_text(const ExponentReport& report);

/// X1(T) of an ensemble run with the tangent map (TransportSummary::mle at the last sample): the
/// ensemble mean [1/s], its standard error, and the spread of the realizations' X1(T) (their sample
/// standard deviation, the standard error times √R). Throws InvalidInput naming `lyapunov` for a
/// run without the tangent map.
struct MleAtEnd {
  double mean = 0, standard_error = 0, spread = 0;
};
MleAtEnd mle_at_end(const TransportSummary& summary);
/// {X1_at_T_per_s, standard_error_per_s, spread_per_s}: what a case's JSON says.
nlohmann::json to_json(const MleAtEnd& mle);

/// Markdown: for each kick, a table of γ (about the cells' m̃2 centre) and one of η (and, with the
/// tangent map, one of X1(T)).
std::string markdown_tables(const std::vector<ExponentCell>& cells, const ExponentTableConfig& config);

/// PREFIX.csv: one row per case, both centres' γ (shown, fit, mean L_d, spreads, realization
/// errors, star) and η; with the tangent map (any cell's summary has `mle`), three more columns:
/// mle (the ensemble mean of X1(T) [1/s]), mle_real_err (its standard error over realizations)
/// and mle_sd (their spread: the sample standard deviation of X1(T)). PREFIX-curves.csv: the mean
/// curves (and then mle, mle_se: ⟨X1(t)⟩ and its standard error). PREFIX-profiles.csv: ⟨E_n(T)⟩.
void write_exponents_csv(std::ostream& out, const std::vector<ExponentCell>& cells);
void write_curves_csv(std::ostream& out, const std::vector<ExponentCell>& cells);
void write_profiles_csv(std::ostream& out, const std::vector<ExponentCell>& cells);

}  // namespace granular
