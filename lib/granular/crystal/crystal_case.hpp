#pragma once
// The `crystal` job's case and its schema (parameter_table.hpp): a packing, its disorder and which
// modes to compute, described once. The tool's options and --help, Python's keywords and
// docstring, validation and the JSON (describe_rows / parse_rows) are all made from
// crystal_parameters(), so a new field costs the field, its row and its use.
//
//   granular::CrystalCase c;                       // an 8 × 8 square packing of steel beads, walls, F0 = 10 N
//   c.packing.lattice = granular::Lattice::hexagonal;
//   c.disorder = {.kind = granular::PackingDisorder::Kind::mass, .width = 0.3};
//   c.near = 30.0;                                 // the 20 modes nearest 30 kHz instead of all
#include <optional>
#include <utility>

#include "granular/crystal/nearest_modes.hpp"
#include "granular/crystal/packing.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

struct CrystalCase {
  /// The packing: lattice, boundary, Lx × Ly, nominal radius, material, F0 (walls) or strain
  /// (periodic). Per-bead radii and materials come from `disorder`.
  PackingSpec packing{};
  /// Drawn per bead; width 0 (the default) is the perfect crystal.
  PackingDisorder disorder{.width = 0};
  /// Every mode (dense LAPACK, small crystals) unless set: then the `count` modes nearest this
  /// frequency [kHz] by sparse shift-invert.
  std::optional<double> near{};
  long count = 20;  ///< with `near`: how many modes, 1 ≤ count < 2N
  /// With `near`: ARPACK (one process), SLEPc (MPI ranks), or automatic: SLEPc from 10⁵ beads.
  NearestMethod method = NearestMethod::automatic;
  /// Every mode in [lo, hi] [kHz] instead (not with `near`): SLEPc's spectrum slicing, over MPI ranks.
  std::optional<std::pair<double, double>> window{};
  /// The window [kHz] of the level-spacing ratio ⟨r⟩; unset: every mode computed.
  std::optional<double> ratio_lo{}, ratio_hi{};
  /// Also the eigenvectors, written as each bead's displacement (PREFIX-modes.csv).
  bool vectors = false;
};

/// The case's rows, in the order front ends show them: the packing, the disorder, the modes.
const ParameterTable<CrystalCase>& crystal_parameters();

/// Throws InvalidInput naming the row of a value out of range, or of one given without what it
/// needs (`count` without `near`, `strain` with walls). The packing's own limits (Lx, radius, ...)
/// are make_packing's.
void validate(const CrystalCase& c);

}  // namespace granular
