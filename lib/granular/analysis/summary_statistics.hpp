#pragma once
// Mean and standard error of per-realization series, summed in realization order so that the
// result is bit-identical whatever the thread or rank count that produced the rows.
#include <cstddef>
#include <span>
#include <vector>

namespace granular {

struct SeriesSummary {
  std::vector<double> mean;
  std::vector<double> standard_error;  ///< sample std / sqrt(R); 0 when R = 1
};

/// `rows[r]` is realization r's series; all rows must have the same length (else InvalidInput).
SeriesSummary summarize(const std::vector<std::span<const double>>& rows);
/// The same for series held as vectors.
SeriesSummary summarize(const std::vector<std::vector<double>>& rows);

}  // namespace granular
