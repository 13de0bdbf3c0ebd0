#pragma once
// Full eigen-decomposition of a symmetric tridiagonal matrix through LAPACK.
//
// The matrix is scaled to unit largest entry before the call (raw SI dynamical matrices have
// entries ~1e10 1/s², where dstemr is known to fail to converge), every `info` is checked, and
// a failing driver falls back to the next one (preferred → stevr → stevd → steqr) instead of returning
// garbage. Workspaces live in the solver, so a loop over realizations allocates nothing.
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "granular/linear/spectrum.hpp"
#include "granular/linear/sym_tridiagonal.hpp"

namespace granular {

struct EigenDecomposition {
  Eigen::VectorXd values;                     ///< ascending
  Eigen::MatrixXd vectors;                    ///< orthonormal columns, empty unless asked for
  LapackDriver driver = LapackDriver::stevr;  ///< the driver that succeeded
  int fallbacks = 0;                          ///< how many drivers failed before it
};

class LapackEigensolver {
 public:
  explicit LapackEigensolver(LapackDriver preferred = LapackDriver::stevd) : preferred_(preferred) {}

  /// Eigenvalues (and eigenvectors) of `t`. Throws NumericalError if every driver fails.
  void solve(const SymTridiagonal& t, bool want_vectors, EigenDecomposition& out);
  EigenDecomposition solve(const SymTridiagonal& t, bool want_vectors) {
    EigenDecomposition out;
    solve(t, want_vectors, out);
    return out;
  }

  /// Eigenpairs number `first` … `last` (1-based, inclusive, ascending): dstemr with
  /// RANGE = 'I' (MRRR, O(N) per pair), falling back to dstevr and then dstebz + dstein.
  /// `out.vectors` is N × (last − first + 1). Throws InvalidInput unless 1 ≤ first ≤ last ≤ N.
  void solve_indices(const SymTridiagonal& t, int first, int last, bool want_vectors, EigenDecomposition& out);
  /// Eigenpairs with lo ≤ λ ≤ hi: the index range from two inertia counts, then solve_indices.
  /// An empty window gives an empty result.
  void solve_window(const SymTridiagonal& t, double lo, double hi, bool want_vectors, EigenDecomposition& out);

 private:
  int run(LapackDriver driver, bool want_vectors, int n, EigenDecomposition& out);
  int run_indices(LapackDriver driver, bool want_vectors, int n, int first, int last, EigenDecomposition& out);
  int run_bisection(bool want_vectors, int n, int first, int last, EigenDecomposition& out);
  LapackDriver preferred_;
  std::vector<double> d_, e_, work_;
  std::vector<int> iwork_, isuppz_;
};

}  // namespace granular
