#pragma once
// Localization and density of states of one (long, possibly streamed) chain over a list of
// frequencies: the transfer-matrix Lyapunov exponent λ(f) with its error, the localization
// length ℓ = 1/λ, and the integrated and differential density of states from node counts —
// the columns of the `localization` tool (SPEC §3, "Infinite chains").
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "granular/ensemble/run_options.hpp"
#include "granular/model/bead_source.hpp"

namespace granular {

struct LocalizationScanConfig {
  std::vector<double> frequency_khz;  ///< [kHz], finite, ≥ 0, strictly increasing (the DOS differences them)
  std::size_t segments = 32;          ///< pieces of the chain for λ's error, ≥ 2 (see TransferMatrixScan)
};

struct LocalizationScan {
  std::vector<double> frequency_khz;
  std::vector<double> lyapunov;             ///< λ [1/bead]
  std::vector<double> lyapunov_error;       ///< standard error of λ from the segments [1/bead]
  std::vector<double> localization_length;  ///< ℓ = 1/λ [beads]; +inf where λ ≤ 0 (inside a band, λ ~ ±1/N)
  std::vector<std::int64_t> modes_below;    ///< eigenfrequencies of the finite chain below f
  std::vector<double> idos;                 ///< modes below f per bead
  std::vector<double> dos;                  ///< d idos / df [1/(bead kHz)], NaN for a single frequency
  std::size_t beads = 0, segments = 0;
};

/// Throws InvalidInput naming `frequencies` or `segments`.
void validate(const LocalizationScanConfig& config);

/// One walk of the chain per thread (run.threads; results do not depend on it). run.progress, if
/// set, advances by bead × frequency steps: size it N × frequencies. Checkpoints are not used
/// (one chain takes seconds). Throws InvalidInput naming `frequencies`, `segments` or `threads`.
LocalizationScan localization_scan(const BeadSource& chain, const LocalizationScanConfig& config,
                                   const RunOptions& run = {});

}  // namespace granular
