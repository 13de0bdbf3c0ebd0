#pragma once
// The modes of a crystal nearest a frequency (docs/crystals.md, "Spectra"), for crystals too large
// for every mode, by shift-invert at σ = (2π f0)²: in one process, ARPACK's Lanczos with (D − σI)⁻¹
// applied by a sparse LDLᵀ factorization (Eigen, fill-reducing ordering) — LDLᵀ does not pivot,
// and D − σI is indefinite: when the modes' residuals exceed 1e-9 of max |D_ij|, they are solved
// again on a pivoted sparse LU; over MPI ranks, SLEPc's Krylov–Schur with MUMPS's pivoted LDLᵀ. "Nearest" is nearest in
// ω² to σ; for a selection narrow beside f0 these are the modes nearest in frequency too.
#include <cstddef>

#include "granular/crystal/crystal_matrix.hpp"
#include "granular/crystal/crystal_spectrum.hpp"

namespace granular {

enum class NearestMethod {
  arpack,     ///< one process (Eigen's LDLᵀ or LU, ARPACK)
  slepc,      ///< collective over MPI_COMM_WORLD: each rank assembles its rows; every rank gets the modes
  automatic,  ///< the faster for the crystal's size: nearest_method_for (docs/performance.md, "Crystals")
};

/// Crystals of at least this many beads take SLEPc when automatic: below it ARPACK's path is the
/// faster (no PETSc or MPI start-up), above it SLEPc's (MUMPS's supernodal LDLᵀ against Eigen's
/// simplicial one); the two cost the same near 10⁵ beads (docs/performance.md, "Crystals").
inline constexpr std::size_t slepc_from_beads = 100000;

/// `method` itself, or for automatic: slepc for crystals of slepc_from_beads or more beads in a
/// build with SLEPc, else arpack. Every rank resolves it alike (SLEPc is collective).
NearestMethod nearest_method_for(NearestMethod method, std::size_t beads);

/// The `count` modes nearest `near_hz` [Hz], by increasing ω², with their IPRs (and unit
/// eigenvectors with config.vectors), as crystal_spectrum gives them, and max_residual. Throws
/// InvalidInput naming `near` (not finite, < 0, or above Gershgorin's bound on the spectrum) or `count` (outside 1 … 2N
/// − 1), NumericalError when D − σI is singular or the solver fails; InvalidInput naming `method` for slepc in a build
/// without SLEPc.
CrystalSpectrum crystal_nearest_modes(const CrystalMatrix& d, double near_hz, long count,
                                      const CrystalSpectrumConfig& config = {},
                                      NearestMethod method = NearestMethod::arpack);

/// Every mode with its frequency in [lo_hz, hi_hz] [Hz], ascending, as crystal_nearest_modes gives
/// them, by SLEPc's spectrum slicing (slepc_window: the count comes from the inertia of MUMPS's
/// LDLᵀ, so no mode of the window is missed and none needs guessing); collective over the MPI ranks
/// as NearestMethod::slepc. Throws InvalidInput naming `window` unless 0 ≤ lo < hi, or when lo is
/// above Gershgorin's bound on the spectrum; naming `method` in a build without SLEPc.
CrystalSpectrum crystal_window_modes(const CrystalMatrix& d, double lo_hz, double hi_hz,
                                     const CrystalSpectrumConfig& config = {});

}  // namespace granular
