#pragma once
// The symmetric tridiagonal matrix as an operator (DESIGN: a solver takes an operator, not a
// chain): the product y = T x, the inertia count "how many eigenvalues lie below σ", and the
// factorized shift-invert solve x ← (T − σI)⁻¹ x, each O(N).
#include <cstddef>
#include <utility>
#include <vector>

#include "granular/linear/sym_tridiagonal.hpp"

namespace granular {

class TridiagonalOperator {
 public:
  /// Keeps a reference: `t` must outlive the operator.
  explicit TridiagonalOperator(const SymTridiagonal& t) : t_(t) {}

  std::size_t rows() const { return t_.size(); }
  const SymTridiagonal& matrix() const { return t_; }
  /// y = T x
  void multiply(const double* x, double* y) const { t_.multiply(x, y); }
  /// Number of eigenvalues strictly below σ: the negative pivots of T − σI = L D Lᵀ
  /// (Sylvester's law of inertia; the Sturm count of LAPACK's bisection, same pivot guard).
  std::size_t count_below(double sigma) const;
  /// Gershgorin interval [lo, hi] that holds every eigenvalue (gershgorin_bounds).
  std::pair<double, double> spectrum_bounds() const { return gershgorin_bounds(t_); }

 private:
  const SymTridiagonal& t_;
};

/// (T − σI)⁻¹ through Gaussian elimination with partial pivoting (LAPACK dgttrf/dgttrs): stable
/// for any shift, including one inside the spectrum where LDLᵀ without pivoting can break down.
/// Factor storage is 4 N doubles + N ints; each solve is O(N) and allocates nothing.
class ShiftInvertOperator {
 public:
  /// Factorizes T − σI. When σ is (numerically) an eigenvalue the factor is singular; the shift
  /// then moves by a few ulps of ‖T‖ (harmless for shift-invert, which only needs σ close).
  void factorize(const SymTridiagonal& t, double sigma);
  std::size_t rows() const { return d_.size(); }
  double shift() const { return sigma_; }
  /// x ← (T − σI)⁻¹ x, in place.
  void solve(double* x) const;
  /// y = (T − σI)⁻¹ x
  void apply(const double* x, double* y) const;

 private:
  std::vector<double> dl_, d_, du_, du2_;
  std::vector<int> ipiv_;
  double sigma_ = 0;
};

}  // namespace granular
