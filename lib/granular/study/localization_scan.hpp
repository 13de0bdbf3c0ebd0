#pragma once
// Localization and density of states of one (long, possibly streamed) chain over a list of
// frequencies: the transfer-matrix Lyapunov exponent λ(f) with its error, the localization
// length ℓ = 1/λ, and the integrated and differential density of states from node counts —
// the columns of the `localization` tool (docs/physics.md, "Infinite chains").
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "granular/ensemble/run_options.hpp"
#include "granular/model/bead_source.hpp"

namespace granular {

struct LocalizationScanConfig {
  std::vector<double> frequency_khz;  ///< [kHz], finite, ≥ 0, strictly increasing (the DOS differences them)
  std::size_t segments = 32;          ///< pieces of the chain for λ's error, 2 … 1e6 (see TransferMatrixScan)
};

struct LocalizationScan {
  std::vector<double> frequency_khz;
  std::vector<double> lyapunov;             ///< λ [1/bead]
  std::vector<double> lyapunov_error;       ///< standard error of λ from the segments [1/bead]
  std::vector<double> localization_length;  ///< ℓ = 1/λ [beads]; +inf where λ ≤ 0 (inside a band, λ ~ ±1/N)
  std::vector<std::uint8_t> resolved;       ///< 1 where ℓ is a measurement (localization_resolved), else 0
  std::vector<std::int64_t> modes_below;    ///< eigenfrequencies of the finite chain below f
  std::vector<double> idos;                 ///< modes below f per bead
  std::vector<double> dos;                  ///< d idos / df [1/(bead kHz)] (see localization_scan)
  std::size_t beads = 0, segments = 0;
};

/// The rule that says when ℓ = 1/λ is a measurement and not a bound: a chain of N beads cut into
/// S segments resolves ℓ iff λ ≥ kResolvedFloorFactor · ln N / N (at f = 0 the recursion grows
/// linearly, λ = ln N / N, so anything near that floor only says ℓ ≳ N) and every segment is at least
/// kResolvedSegmentFactor · ℓ long (the batch-means error of λ assumes independent segments).
inline constexpr double kResolvedFloorFactor = 10;
inline constexpr double kResolvedSegmentFactor = 10;
bool localization_resolved(double lyapunov, std::size_t beads, std::size_t segments);
/// The rule above in words, for the JSON metadata and the docs.
const char* localization_resolved_rule();

/// The step [kHz] of the central difference that gives the DOS when only one frequency is asked
/// for (node counts at f ± step/2, one-sided from f at f < step/2).
inline constexpr double kSingleFrequencyDosStepKhz = 0.01;

/// Throws InvalidInput naming `f` (the frequencies: finite, >= 0, increasing) or `segments` (2 … 1e6):
/// the one check of the localization tool and granular.localization.
void validate(const LocalizationScanConfig& config);

/// One walk of the chain per thread (run.threads; results do not depend on it). run.progress, if
/// set, advances by bead × frequency steps: size it N × frequencies. Checkpoints are not used
/// (one chain takes seconds). The DOS differences neighbouring frequencies; with one frequency it
/// counts modes at f ± kSingleFrequencyDosStepKhz / 2 as well (two more walks of the chain). Throws InvalidInput naming
/// `f`, `segments` or `threads`.
LocalizationScan localization_scan(const BeadSource& chain, const LocalizationScanConfig& config,
                                   const RunOptions& run = {});

}  // namespace granular
