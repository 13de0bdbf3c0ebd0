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
#include "granular/parameter_table.hpp"

namespace granular {

struct CrystalIprMapConfig {
  /// The crystal: its packing (lattice, boundary, Lx, Ly, radius, F0 or strain) and its disorder's
  /// kind and seed; `widths` sets the disorder's width, and the case's modes choice is not used.
  CrystalCase crystal{};
  std::vector<double> widths{0.0, 0.5, 0.9};  ///< disorder strengths w in [0, 1)
  unsigned long realizations = 10;            ///< ≥ 1
  double bin_hz = 1000;  ///< bins [k W, (k + 1) W) [Hz], k = 0 … ⌊f_max/W⌋ over the cell's modes
  /// Realizations solved at once; 0: OMP_NUM_THREADS, else every core. The map is bit-identical for
  /// any count (each realization fills its own slot, and the slots are summed in order).
  int threads = 1;
};

/// The map's rows: the crystal's own (crystal_parameters(): packing, disorder kind, seed), then
/// widths, realizations, bin_hz, threads. The front ends' options and keywords, and the JSON.
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

/// One cell per width, in the order given, each by every mode of each realization (crystal_spectrum:
/// for crystals of up to a few thousand beads). Throws InvalidInput naming `widths`,
/// `realizations`, `bin_hz` or the packing's field before any work, and `packing` when a
/// realization is not rigid (static_state).
std::vector<CrystalIprMapCell> crystal_ipr_map(const CrystalIprMapConfig& config);

}  // namespace granular
