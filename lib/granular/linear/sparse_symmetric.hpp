#pragma once
// A real symmetric sparse matrix in compressed rows (CSR), both triangles stored: the form in
// which a two-dimensional crystal's dynamical matrix (2 × 2 blocks per contact) reaches the
// shift-invert eigensolvers, and in which a rank hands PETSc its own rows.
#include <cstddef>
#include <vector>

namespace granular {

struct SparseSymmetric {
  std::size_t n = 0;                   ///< rows = columns
  std::vector<std::size_t> row_start;  ///< n + 1 offsets into column/value; row i is [row_start[i], row_start[i+1])
  std::vector<std::size_t> column;     ///< column of each entry, ascending within a row
  std::vector<double> value;           ///< A(i, column) of each entry

  std::size_t size() const { return n; }
  std::size_t nonzeros() const { return value.size(); }
  /// y = A x (x and y of length n, not overlapping)
  void multiply(const double* x, double* y) const;
};

/// The n × n matrix whose entries are the sums of the triplets (rows[k], columns[k], values[k])
/// (repeated positions add, as contacts add their blocks to a bead's diagonal), each summed in
/// ascending order of its values: independent of the triplets' order, so that A(j, i), made of the
/// same numbers as A(i, j), is equal to it to the bit. Throws InvalidInput naming `matrix` when the
/// lists differ in length, an index is ≥ n or a value is not finite, or when the sum is not exactly
/// symmetric.
SparseSymmetric sparse_from_triplets(std::size_t n, const std::vector<std::size_t>& rows,
                                     const std::vector<std::size_t>& columns, const std::vector<double>& values);

}  // namespace granular
