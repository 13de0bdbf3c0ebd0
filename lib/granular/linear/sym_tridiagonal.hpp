#pragma once
// A real symmetric tridiagonal matrix kept as its two diagonals.
#include <cstddef>
#include <utility>
#include <vector>

namespace granular {

struct SymTridiagonal {
  std::vector<double> diagonal;      ///< n entries
  std::vector<double> off_diagonal;  ///< n-1 entries: T(i, i+1) = T(i+1, i)

  std::size_t size() const { return diagonal.size(); }
  /// y = T x
  void multiply(const double* x, double* y) const;
  /// max |entry|, the scale used to keep LAPACK's arithmetic away from over/underflow;
  /// throws InvalidInput when an entry is NaN or infinite
  double max_abs() const;
  /// false if any entry is NaN or infinite (max_abs alone would skip a NaN)
  bool all_finite() const;
};

/// How gershgorin_bounds rounds the bound of row i, d_i ∓ (|e_{i−1}| + |e_i|).
enum class RowSum {
  radius_first,   ///< d_i ∓ (|e_{i−1}| + |e_i|)
  left_to_right,  ///< (d_i ∓ |e_{i−1}|) ∓ |e_i|, as the row reads
};

/// The Gershgorin interval [lo, hi] that holds every eigenvalue of `t` (+inf, −inf when empty).
/// Both sums give the same bound up to the last bit; each caller keeps the one its results were
/// first computed with, so that they stay the same bit for bit (radius_first: the bisection's
/// starting brackets; left_to_right: the time-step rule's ω_max, the partial spectrum's cluster scale).
std::pair<double, double> gershgorin_bounds(const SymTridiagonal& t, RowSum sum = RowSum::radius_first);

}  // namespace granular
