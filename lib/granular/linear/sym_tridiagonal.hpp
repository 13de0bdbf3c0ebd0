#pragma once
// A real symmetric tridiagonal matrix kept as its two diagonals.
#include <cstddef>
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

}  // namespace granular
