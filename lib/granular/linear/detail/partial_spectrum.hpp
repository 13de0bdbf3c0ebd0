#pragma once
// Partial spectra of long chains, the backend of spectrum() for nearest/window selections: the K modes nearest a
// frequency, or every mode in a frequency window, with their displacement IPRs, by one of four interchangeable methods:
//   lapack  dstemr (MRRR) restricted to an index range found by two O(N) inertia counts;
//   bisect  the same index range by many-shift Sturm bisection (sturm_bisection.hpp), vectors by
//           inverse iteration: on a window of the chain for a localized mode (localized_modes.hpp),
//           else in the whole chain, several modes at once: the fastest for long chains;
//   arpack  ARPACK shift-invert around σ = (2π f)², (T − σI)⁻¹ by an O(N) tridiagonal LU;
//   slepc   SLEPc Krylov–Schur + shift-invert on a PETSc MPI matrix (collective: under mpirun
//           every rank calls it with the same matrix and gets the same result).
// "Nearest" means nearest in frequency |f − f0| (ties: lower mode first); results are sorted
// by increasing frequency and carry their mode numbers 1…N in the full spectrum.
#include <cstddef>
#include <string_view>
#include <vector>

#include "granular/linear/spectrum.hpp"
#include "granular/linear/sym_tridiagonal.hpp"

namespace granular {

namespace detail {
/// Test seam (tests only): when set, called with each method's computed candidates (ascending
/// ω²) before the selection; the candidate at the returned index is dropped (an index ≥ size
/// drops none). It lets a test hide an eigenvalue from a solver, as ARPACK/SLEPc may do silently.
using CandidateSeam = std::size_t (*)(std::string_view method, const std::vector<double>& values);
extern CandidateSeam hide_candidate;
}  // namespace detail

/// The selected modes of the dynamical matrix `t` (docs/physics.md, "The linear spectrum") with IPRs from m^{-1/2}
/// (`inverse_sqrt_mass`, N entries), by config.method (lapack | bisect | arpack | slepc; its
/// vectors, tolerance, subspace and lanes): every field of the Spectrum but `clustered` and
/// info.max_residual, which SpectrumSolver adds; `residual` always (‖T w − ω² w‖ / ‖T‖_max for
/// unit w). Throws InvalidInput for a bad selection or method, NumericalError when a solver fails.
/// For slepc this call is collective over MPI_COMM_WORLD.
/// Every result is checked by inertia (node) counts: the modes must be exactly the true
/// eigenvalues numbered first..last, none left out (window: all of the window's; nearest: none
/// nearer than the farthest returned). A result that fails (or a solver that throws
/// NumericalError) is recomputed by bisect, recorded in info.method ("arpack→bisect") and
/// info.fallbacks; if bisect fails too, NumericalError (naming both failures).
Spectrum partial_spectrum(const SymTridiagonal& t, const std::vector<double>& inverse_sqrt_mass,
                          const ModeSelection& selection, const SpectrumConfig& config);

}  // namespace granular
