#pragma once
// Eigenpairs of a symmetric tridiagonal matrix nearest a shift σ, by shift-and-invert Krylov
// methods: ARPACK (dsaupd/dseupd, mode 3) and SLEPc (Krylov–Schur + ST sinvert on a PETSc
// MPI matrix). Both see the matrix only through TridiagonalOperator / ShiftInvertOperator
// (ARPACK) or its rows (SLEPc); partial_spectrum.hpp is the one call users make.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "granular/error.hpp"
#include "granular/linear/sparse_symmetric.hpp"
#include "granular/linear/sym_tridiagonal.hpp"

namespace granular {

struct ShiftInvertConfig {
  int count = 1;            ///< eigenpairs wanted (the `count` nearest σ in |λ − σ|)
  double tolerance = 0;     ///< relative residual of the Ritz pairs; 0 = machine precision (ARPACK),
                            ///< 1e-14 for SLEPc
  int max_restarts = 3000;  ///< ARPACK iparam(3) / SLEPc max_it
  int subspace = 0;         ///< Krylov basis size (ncv); 0 = max(2 count + 1, 20), capped at N
};

struct ShiftInvertResult {
  std::vector<double> values;  ///< ascending
  Eigen::MatrixXd vectors;     ///< N × count, orthonormal columns (on every rank for SLEPc)
  int restarts = 0;            ///< outer iterations the method reported
  long operator_solves = 0;    ///< (T − σI)⁻¹ applications (ARPACK; SLEPc reports its iterations only)
};

/// Throws InvalidInput naming `solver` unless 1 ≤ count ≤ N − 1 (a Krylov method needs a
/// dimension to spare).
inline void require_nearest_count(const char* solver, std::size_t n, long count) {
  if (count < 1 || count > static_cast<long>(n) - 1)
    throw InvalidInput(solver, ": " + std::to_string(count) + " eigenpairs of an N = " + std::to_string(n) +
                                   " matrix; it needs 1 <= count <= N - 1 (use method lapack)");
}

/// ARPACK shift-invert (dsaupd/dseupd, mode 3) on any symmetric operator of size n: `solve(x, y)`
/// sets y = (A − shift I)⁻¹ x. The `count` eigenvalues of A nearest `shift`, ascending, with unit
/// vectors. Throws InvalidInput unless 1 ≤ count ≤ n − 1, NumericalError when ARPACK fails.
/// ARPACK is not reentrant: calls from several threads run one after another (a process-wide lock).
ShiftInvertResult arpack_shift_invert(int n, double shift, const std::function<void(const double*, double*)>& solve,
                                      const ShiftInvertConfig& config);

/// ARPACK shift-invert on a tridiagonal matrix. Throws InvalidInput unless 1 ≤ count ≤ N − 1, NumericalError when
/// ARPACK fails or does not converge.
ShiftInvertResult arpack_nearest(const SymTridiagonal& t, double sigma, const ShiftInvertConfig& config);

/// SLEPc shift-invert, collective over MPI_COMM_WORLD: every rank passes the same matrix, owns
/// a block of its rows, and receives the full result. Initializes SLEPc (and MPI) on first use
/// and finalizes it at exit. Loads the SLEPc component (slepc_component.hpp) on first use: throws
/// IoError when it is missing, InvalidInput when this build has no SLEPc.
ShiftInvertResult slepc_nearest(const SymTridiagonal& t, double sigma, const ShiftInvertConfig& config);

/// SLEPc shift-invert of a sparse symmetric matrix (a crystal's dynamical matrix), collective as
/// above: every rank passes the same matrix and assembles only the rows PETSc gives it.
ShiftInvertResult slepc_nearest(const SparseSymmetric& a, double sigma, const ShiftInvertConfig& config);

/// Every eigenpair of a sparse symmetric matrix with its eigenvalue in [lo, hi], ascending, by
/// SLEPc's spectrum slicing (Krylov–Schur, shift-and-invert at shifts across the interval, the count
/// below each shift from the inertia of MUMPS's LDLᵀ), collective as slepc_nearest: no count to
/// guess, and none missed. Throws InvalidInput naming `window` unless lo < hi (both finite),
/// naming `method` in a build without SLEPc.
ShiftInvertResult slepc_window(const SparseSymmetric& a, double lo, double hi);

/// True when the library was built with SLEPc (its component may still be missing at run time).
bool have_slepc();

}  // namespace granular
