#pragma once
// Partial spectra of long chains (issue 3): the K modes nearest a frequency, or every mode in a
// frequency window, with their displacement IPRs, by one of four interchangeable methods:
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

#include "granular/linear/sym_tridiagonal.hpp"

namespace granular {

enum class PartialMethod { lapack, bisect, arpack, slepc };
std::string_view to_string(PartialMethod method);
/// "lapack" | "bisect" | "arpack" | "slepc"; throws InvalidInput naming --method.
PartialMethod parse_partial_method(std::string_view name);

/// Which modes: the `count` nearest `near_khz`, or all in [lo_khz, hi_khz].
struct SpectrumSelection {
  enum class Kind { nearest, window } kind = Kind::nearest;
  double near_khz = 0;  ///< nearest: target frequency [kHz], finite, >= 0
  long count = 0;       ///< nearest: how many modes, 1 <= count <= N
  double lo_khz = 0;    ///< window: band [lo, hi] in kHz, 0 <= lo <= hi, both inclusive
  double hi_khz = 0;

  static SpectrumSelection nearest(double khz, long count) { return {Kind::nearest, khz, count, 0, 0}; }
  static SpectrumSelection window(double lo, double hi) { return {Kind::window, 0, 0, lo, hi}; }
};

/// Throws InvalidInput (naming --near, --count or --window) unless the selection makes sense for
/// an N-bead chain: K ≤ 0 and K > N are errors; --near above the spectrum is not (it selects the
/// top modes); a window without modes is valid and gives an empty result.
void validate(const SpectrumSelection& selection, std::size_t n);

/// The command-line form: exactly one of (--near with --count) or --window "F1:F2".
/// Throws InvalidInput naming the option for a missing/extra/malformed one.
SpectrumSelection parse_selection(const std::optional<double>& near_khz, const std::optional<long>& count,
                                  const std::optional<std::string>& window);

struct PartialSpectrumConfig {
  PartialMethod method = PartialMethod::lapack;
  bool keep_vectors = false;  ///< return the eigenvectors (N × K) too
  double tolerance = 0;       ///< ARPACK/SLEPc Ritz tolerance; 0 = each method's tightest default
  int subspace = 0;           ///< ARPACK/SLEPc Krylov basis size; 0 = max(2K + 1, 20)
  std::size_t lanes = 8;      ///< bisect: eigenvectors computed together (memory 2 N × lanes doubles)
};

struct PartialSpectrum {
  std::vector<std::size_t> mode;  ///< mode numbers 1…N in the full spectrum (increasing frequency)
  std::vector<double> omega2;     ///< eigenvalues ω² [1/s²], ascending
  std::vector<double> freq_khz;   ///< f = ω / 2π [kHz]
  std::vector<double> ipr;        ///< displacement IPR Σv⁴/(Σv²)², v = M^{-1/2} w
  std::vector<double> residual;   ///< ‖T w − ω² w‖ / ‖T‖_max for unit w (a check, always computed)
  Eigen::MatrixXd vectors;        ///< N × K unit eigenvectors w of T (sign: largest entry > 0), if kept
  std::string method;             ///< what ran ("lapack-stevr", "arpack", "slepc")
  int restarts = 0;               ///< ARPACK/SLEPc outer iterations
  int candidates = 0;             ///< eigenpairs computed to select from (≥ K)
  std::size_t size() const { return omega2.size(); }
};

/// The selected modes of the dynamical matrix `t` (SPEC §3) with IPRs from m^{-1/2}
/// (`inverse_sqrt_mass`, N entries). Throws InvalidInput for a bad selection or method,
/// NumericalError when a solver fails. For slepc this call is collective over MPI_COMM_WORLD.
PartialSpectrum partial_spectrum(const SymTridiagonal& t, const std::vector<double>& inverse_sqrt_mass,
                                 const SpectrumSelection& selection, const PartialSpectrumConfig& config = {});

/// ω² [1/s²] of a frequency in kHz.
double omega_squared_of_khz(double khz);

/// Writes `spectrum` (mode, omega2, freq_khz, ipr, residual, and the eigenvectors if kept) and
/// `inverse_sqrt_mass` to an HDF5 file, atomically. Datasets: /mode, /omega2, /freq_khz, /ipr,
/// /residual (K), /inverse_sqrt_mass (N), /eigenvectors (K × N, row j = unit w of mode j;
/// displacements are v = w ⊙ inverse_sqrt_mass). Throws IoError.
void write_partial_spectrum_hdf5(const std::string& path, const PartialSpectrum& spectrum,
                                 const std::vector<double>& inverse_sqrt_mass);

}  // namespace granular
