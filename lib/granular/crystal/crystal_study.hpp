#pragma once
// The `crystal` job in one call (docs/crystals.md): the packing of a CrystalCase, its static state,
// its dynamical matrix and the modes the case asks for — every mode by dense LAPACK, or the
// `count` nearest `near` by sparse shift-invert (ARPACK, or SLEPc collective over MPI ranks:
// every rank calls it with the same case and receives the whole result) — with the level-spacing
// ratio of the frequencies computed. The tool and granular.crystal are parse → this → write.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "granular/crystal/crystal_case.hpp"
#include "granular/crystal/crystal_matrix.hpp"
#include "granular/crystal/crystal_spectrum.hpp"
#include "granular/crystal/nearest_modes.hpp"
#include "granular/crystal/packing.hpp"
#include "granular/crystal/static_state.hpp"

namespace granular {

struct CrystalResult {
  Packing packing;
  StaticState state;
  /// The modes computed, by increasing ω²: every mode, or the `count` nearest `near`.
  CrystalSpectrum spectrum;
  SpacingRatio ratio;        ///< ⟨r⟩ of the computed frequencies inside [ratio_lo, ratio_hi]
  std::string method;        ///< "lapack" (every mode, dsyevd), "arpack" or "slepc" (nearest modes)
  CrystalMatrix matrix;      ///< D, as solved (what `crystal --dump-matrix` writes)
  double solve_seconds = 0;  ///< wall time of the eigensolver alone (not the packing, state or matrix)
};

/// Validates `c` and runs it. Throws InvalidInput naming the row of a bad value, or `packing` for a
/// packing that is not rigid under its load; NumericalError when a solver fails.
CrystalResult crystal_study(const CrystalCase& c);

/// The run's metadata: the case (describe_rows of crystal_parameters()), the packing's size and
/// contacts, the static state (Newton steps, force imbalance, opened contacts) and the spectrum
/// (method, modes, ⟨r⟩ and its window).
nlohmann::json describe(const CrystalCase& c, const CrystalResult& r);

}  // namespace granular
