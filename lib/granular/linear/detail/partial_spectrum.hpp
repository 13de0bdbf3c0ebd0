#pragma once
// Partial spectra of long chains, the backend of spectrum() for nearest/window selections: the K modes nearest a
// frequency, or every mode in a frequency window, with their displacement IPRs, by one of four interchangeable methods:
//   lapack  dstemr (MRRR) restricted to an index range found by two O(N) inertia counts;
//   bisect  the same index range by many-shift Sturm bisection (sturm_bisection.hpp), vectors by
//           LAPACK inverse iteration (dstein): the fastest for long chains;
//   arpack  ARPACK shift-invert around σ = (2π f)², (T − σI)⁻¹ by an O(N) tridiagonal LU;
//   slepc   SLEPc Krylov–Schur + shift-invert on a PETSc MPI matrix (collective: under mpirun
//           every rank calls it with the same matrix and gets the same result).
// "Nearest" means nearest in frequency |f − f0| (ties: lower mode first); results are sorted
// by increasing frequency and carry their mode numbers 1…N in the full spectrum.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "granular/linear/spectrum.hpp"
#include "granular/linear/sym_tridiagonal.hpp"

namespace granular {

struct PartialSpectrumConfig {
  SpectrumMethod method = SpectrumMethod::lapack;  ///< lapack | bisect | arpack | slepc
  bool keep_vectors = false;                       ///< return the eigenvectors (N × K) too
  double tolerance = 0;                            ///< ARPACK/SLEPc Ritz tolerance; 0 = each method's tightest default
  int subspace = 0;                                ///< ARPACK/SLEPc Krylov basis size; 0 = max(2K + 1, 20)
  std::size_t lanes = 8;  ///< bisect: eigenvectors computed together (memory 2 N × lanes doubles)
};

struct PartialSpectrum {
  std::vector<std::size_t> mode;  ///< mode numbers 1…N in the full spectrum (increasing frequency)
  std::vector<double> omega2;     ///< eigenvalues ω² [1/s²], ascending
  std::vector<double> freq_khz;   ///< f = ω / 2π [kHz]
  std::vector<double> ipr;        ///< displacement IPR Σv⁴/(Σv²)², v = M^{-1/2} w
  std::vector<double> residual;   ///< ‖T w − ω² w‖ / ‖T‖_max for unit w (a check, always computed)
  Eigen::MatrixXd vectors;        ///< N × K unit eigenvectors w of T (sign: largest entry > 0), if kept
  std::string method;             ///< what ran ("lapack-stevr", "arpack", "slepc", "arpack→bisect" after a fallback)
  int restarts = 0;               ///< ARPACK/SLEPc outer iterations
  int candidates = 0;             ///< eigenpairs computed to select from (≥ K)
  int fallbacks = 0;              ///< 1 when the first method failed the node-count check and bisect ran
  std::string note;               ///< why the fallback ran (empty otherwise)
  std::size_t size() const { return omega2.size(); }
};

namespace detail {
/// Test seam (tests only): when set, called with each method's computed candidates (ascending
/// ω²) before the selection; the candidate at the returned index is dropped (an index ≥ size
/// drops none). It lets a test hide an eigenvalue from a solver, as ARPACK/SLEPc may do silently.
using CandidateSeam = std::size_t (*)(std::string_view method, const std::vector<double>& values);
extern CandidateSeam hide_candidate;
}  // namespace detail

/// The selected modes of the dynamical matrix `t` (SPEC §3) with IPRs from m^{-1/2}
/// (`inverse_sqrt_mass`, N entries). Throws InvalidInput for a bad selection or method,
/// NumericalError when a solver fails. For slepc this call is collective over MPI_COMM_WORLD.
/// Every result is checked by inertia (node) counts: the modes must be exactly the true
/// eigenvalues numbered first..last, none left out (window: all of the window's; nearest: none
/// nearer than the farthest returned). A result that fails (or a solver that throws
/// NumericalError) is recomputed by bisect, recorded in `method` ("arpack→bisect"), `fallbacks`
/// and `note`; if bisect fails too, NumericalError.
PartialSpectrum partial_spectrum(const SymTridiagonal& t, const std::vector<double>& inverse_sqrt_mass,
                                 const ModeSelection& selection, const PartialSpectrumConfig& config = {});

}  // namespace granular
