#pragma once
// The 2D analogue of the paper's IPR map (docs/crystals.md, "The IPR map"): the mean vector IPR
// and the level-spacing ratio ⟨r⟩ of a disordered crystal's modes, in frequency bins, for each
// disorder strength, over realizations. Realization r of every strength draws from the random
// stream (seed, r), so the strengths share their random numbers (common random numbers).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "granular/crystal/crystal_case.hpp"
#include "granular/crystal/packing.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

struct CrystalIprMapConfig {
  /// The crystal: its packing (lattice, boundary, Lx, Ly, radius, F0 or strain), its disorder's
  /// kind and seed, and which modes: every one (dense LAPACK), or with `near` the `count` nearest
  /// it (ARPACK's shift-invert, one process per crystal: for crystals too large for every mode).
  /// `widths` sets the disorder's width; the case's `method`, `window` and `vectors` are not used.
  CrystalCase crystal{};
  std::vector<double> widths{0.0, 0.5, 0.9};  ///< disorder strengths w in [0, 1)
  unsigned long realizations = 10;            ///< ≥ 1
  double bin_hz = 1000;  ///< bins [k W, (k + 1) W) [Hz], k = 0 … ⌊f_max/W⌋ over the cell's modes
};

/// The map's rows: the crystal's own (crystal_parameters(): packing, disorder kind, seed, near,
/// count), then
/// widths, realizations, bin_hz. The front ends' options and keywords, and the JSON (which a
/// checkpoint must match to be resumed).
const ParameterTable<CrystalIprMapConfig>& crystal_ipr_map_parameters();

struct CrystalIprMapCell {
  double width = 0;
  std::vector<std::size_t> bin_modes;  ///< modes of all realizations in each bin (f < 0, a torus's
                                       ///< round-off zero modes, counts in bin 0)
  std::vector<double> bin_ipr;         ///< their mean vector IPR (NaN for an empty bin)
  /// ⟨r⟩ of the levels in the bin, each realization's ratios pooled (NaN without any), and how many.
  std::vector<double> bin_ratio;
  std::vector<std::size_t> bin_ratios;
};

/// Throws InvalidInput naming `widths`, `realizations`, `bin_hz` or the packing's field (what
/// crystal_ipr_map checks before any work; front ends call it before claiming their outputs).
void validate(const CrystalIprMapConfig& config);

/// One cell per width, in the order given, each by every mode of each realization (crystal_spectrum:
/// for crystals of up to a few thousand beads) or its `count` modes nearest `near`
/// (crystal_nearest_modes); the bins still start at 0 Hz, so those below the modes stay empty. The widths ×
/// realizations crystals run as one ensemble (ensemble_runner.hpp): on `run.threads` threads, dealt to the ranks under
/// mpirun (rank 0 alone gets the cells; the others an empty vector), each crystal's frequencies and IPRs logged to
/// `run.checkpoint` as it finishes and not recomputed on `run.resume`. The cells are made from the crystals in index
/// order, so they are bit-identical for any thread or rank count and across an interruption. Throws InvalidInput naming
/// `widths`, `realizations`, `bin_hz`, the packing's field or the run option (`skip_failed` is refused: a crystal that
/// is not rigid is a wrong case, not a numerical accident) before any work, and `packing` when a realization is not
/// rigid.
std::vector<CrystalIprMapCell> crystal_ipr_map(const CrystalIprMapConfig& config, const RunOptions& run = {});

}  // namespace granular
