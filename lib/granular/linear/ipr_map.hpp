#pragma once
// Mean frequency and IPR of every mode over realizations, on a grid of (q, ξ) (SPEC §3;
// the paper's IPR-map figure). Realization r of a cell uses the bead types of realization r
// of the seed, so all ξ of one q share their configurations (common random numbers).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "granular/ensemble/progress_meter.hpp"
#include "granular/linear/partial_spectrum.hpp"
#include "granular/model/disorder.hpp"
#include "granular/model/material.hpp"

namespace granular {

struct IprMapConfig {
  Disorder disorder = Disorder::anderson;
  std::vector<double> q_values{0.2, 0.5, 0.8};
  std::vector<double> xi_values;      ///< size ratios R2/R1 in (0, 1]
  std::size_t n = 100;                ///< beads per chain
  double precompression = 10;         ///< F0 [N], > 0
  std::size_t realizations = 100;
  std::uint64_t seed = 1;
  double r1 = 4.76e-3;                ///< type-1 radius [m]
  Material material = steel;
  int threads = 0;                    ///< 0 = every core
  std::string solver = "fast";        ///< see make_mode_ipr_solver (full spectrum only)
  /// Partial spectra (--near/--count or --window): only these modes of each realization, by
  /// `partial_method`. Unset: every mode, as before.
  std::optional<SpectrumSelection> selection;
  PartialMethod partial_method = PartialMethod::lapack;  ///< arpack/slepc run on one thread
};

struct IprMapCell {
  double q = 0, xi = 0;
  std::vector<double> freq_khz;  ///< mean over realizations, mode k at index k-1
  std::vector<double> ipr;       ///< mean over realizations
  /// With a selection the rows are not averaged (mode numbers and, for a window, counts differ
  /// between realizations): every selected mode of every realization is one row, realization-major,
  /// by increasing frequency; `mode` holds its mode number and `realization` its realization.
  /// Both stay empty for the full spectrum.
  std::vector<std::size_t> mode;
  std::vector<std::uint64_t> realization;
};

/// Throws InvalidInput on a bad config before any work starts.
void validate(const IprMapConfig& config);

/// One cell per (q, ξ), q-major. Bit-identical for any thread count.
std::vector<IprMapCell> compute_ipr_map(const IprMapConfig& config, ProgressMeter* progress = nullptr);

}  // namespace granular
