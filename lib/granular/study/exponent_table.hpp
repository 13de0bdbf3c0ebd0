#pragma once
// The paper's whole protocol (SPEC §4): transport exponents γ (m̃2 ∝ t^γ) and η (P⁻¹ ∝ t^−η)
// for every chain kind × precompression × kick, each an ensemble (transport_study.hpp).
// Homogeneous chains are deterministic, so they run one realization whatever R is.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "granular/study/transport_study.hpp"

namespace granular {

struct ExponentTableConfig {
  std::vector<Disorder> chains{Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2};
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
};

struct ExponentRunOptions {
  int threads = 0;
  std::string checkpoint_prefix;  ///< case i logs to <prefix>.<i>; empty: no checkpoints
  bool resume = false;
  int progress = -1;  ///< ProgressMeter's enabled flag
  ProgressMeter* meter =
      nullptr;  ///< optional: advance this meter (total: every case's realizations) instead of one of its own
  std::function<bool()> cancelled{};  ///< see RunOptions::cancelled
  bool skip_failed = false;           ///< see RunOptions::skip_failed
};

/// The cases in table order (kick-major, then F0, then chain); with automatic_length each sized
/// (N, the centre kick, the centred draw) by automatic_chain_length.
std::vector<TransportCase> exponent_cases(const ExponentTableConfig& config);

/// Runs every case; under mpirun only rank 0 gets filled summaries. Memory: one case's
/// records at a time (transport_study.hpp), then its summary.
std::vector<ExponentCell> run_exponent_table(const ExponentTableConfig& config, const ExponentRunOptions& options);

/// One table cell: "1.763 ± 0.012 (± 0.020 real.)", the shown value ± its sub-window spread and
/// (when an ensemble gave one) its realization error; a trailing * marks a starred cell (not a
/// power law: the value is the mean L_d over the fit window).
std::string cell_text(const ExponentReport& report);

/// Markdown: for each kick, a table of γ (about the cells' m̃2 centre) and one of η.
std::string markdown_tables(const std::vector<ExponentCell>& cells, const ExponentTableConfig& config);

/// PREFIX.csv: one row per case, both centres' γ (shown, fit, mean L_d, spreads, realization
/// errors, star) and η. PREFIX-curves.csv: the mean curves. PREFIX-profiles.csv: ⟨E_n(T)⟩.
void write_exponents_csv(std::ostream& out, const std::vector<ExponentCell>& cells);
void write_curves_csv(std::ostream& out, const std::vector<ExponentCell>& cells);
void write_profiles_csv(std::ostream& out, const std::vector<ExponentCell>& cells);

}  // namespace granular
