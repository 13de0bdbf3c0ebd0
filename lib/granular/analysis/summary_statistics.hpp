#pragma once
// Mean and standard error of per-realization series, summed in realization order so that the
// result is bit-identical whatever the thread or rank count that produced the rows.
#include <cstddef>
#include <limits>
#include <vector>

namespace granular {

struct SeriesSummary {
  std::vector<double> mean;
  std::vector<double> standard_error;  ///< sample std / sqrt(R); 0 when R = 1
};

/// `rows[r]` is realization r's series; all rows must have the same length.
SeriesSummary summarize(const std::vector<std::vector<double>>& rows);

/// The series held in columns [begin, begin + count) of the first `row_count` rows (all by
/// default), without copying them out. Throws InvalidInput if a row is too short.
SeriesSummary summarize(const std::vector<std::vector<double>>& rows, std::size_t begin, std::size_t count,
                        std::size_t row_count = std::numeric_limits<std::size_t>::max());

}  // namespace granular
