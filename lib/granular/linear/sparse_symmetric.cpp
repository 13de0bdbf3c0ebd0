#include "granular/linear/sparse_symmetric.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "granular/error.hpp"

namespace granular {

void SparseSymmetric::multiply(const double* x, double* y) const {
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0;
    for (std::size_t k = row_start[i]; k < row_start[i + 1]; ++k) sum += value[k] * x[column[k]];
    y[i] = sum;
  }
}

SparseSymmetric sparse_from_triplets(std::size_t n, const std::vector<std::size_t>& rows,
                                     const std::vector<std::size_t>& columns, const std::vector<double>& values) {
  if (rows.size() != columns.size() || rows.size() != values.size())
    throw InvalidInput("matrix", ": " + std::to_string(rows.size()) + " rows, " + std::to_string(columns.size()) +
                                     " columns and " + std::to_string(values.size()) + " values given");
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (rows[k] >= n || columns[k] >= n)
      throw InvalidInput("matrix", ": entry (" + std::to_string(rows[k]) + ", " + std::to_string(columns[k]) +
                                       ") outside an n = " + std::to_string(n) + " matrix");
    if (!std::isfinite(values[k])) throw InvalidInput("matrix", ": a value is not finite");
  }
  // Sort by (row, column, value) and sum repeats in that order: the sum does not depend on the
  // order of the triplets, so A(i, j) and A(j, i), made of the same numbers, are equal to the bit.
  std::vector<std::size_t> order(rows.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (rows[a] != rows[b]) return rows[a] < rows[b];
    return columns[a] != columns[b] ? columns[a] < columns[b] : values[a] < values[b];
  });
  SparseSymmetric a;
  a.n = n;
  a.row_start.assign(n + 1, 0);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t i = rows[order[k]], j = columns[order[k]];
    if (k > 0 && rows[order[k - 1]] == i && columns[order[k - 1]] == j) {
      a.value.back() += values[order[k]];
      continue;
    }
    a.column.push_back(j);
    a.value.push_back(values[order[k]]);
    ++a.row_start[i + 1];
  }
  std::partial_sum(a.row_start.begin(), a.row_start.end(), a.row_start.begin());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = a.row_start[i]; k < a.row_start[i + 1]; ++k) {
      const std::size_t j = a.column[k];
      const auto first = a.column.begin() + static_cast<std::ptrdiff_t>(a.row_start[j]);
      const auto last = a.column.begin() + static_cast<std::ptrdiff_t>(a.row_start[j + 1]);
      const auto at = std::lower_bound(first, last, i);
      if (at == last || *at != i || a.value[static_cast<std::size_t>(at - a.column.begin())] != a.value[k])
        throw InvalidInput("matrix", ": not symmetric at (" + std::to_string(i) + ", " + std::to_string(j) + ")");
    }
  return a;
}

}  // namespace granular
