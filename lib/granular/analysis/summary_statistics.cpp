#include "granular/analysis/summary_statistics.hpp"

#include <algorithm>
#include <cmath>

#include "granular/error.hpp"

namespace granular {

SeriesSummary summarize(const std::vector<std::vector<double>>& rows, std::size_t begin, std::size_t n,
                        std::size_t row_count) {
  SeriesSummary s;
  const std::size_t count = std::min(row_count, rows.size());
  if (count == 0) return s;
  const double r = static_cast<double>(count);
  s.mean.assign(n, 0.0);
  s.standard_error.assign(n, 0.0);
  for (std::size_t k = 0; k < count; ++k) {
    if (rows[k].size() < begin + n) throw InvalidInput("summarize: a realization's series is too short");
    for (std::size_t i = 0; i < n; ++i) s.mean[i] += rows[k][begin + i];
  }
  for (double& m : s.mean) m /= r;
  if (count < 2) return s;
  for (std::size_t k = 0; k < count; ++k)  // two passes: no cancellation from E[x²] − E[x]²
    for (std::size_t i = 0; i < n; ++i) {
      const double d = rows[k][begin + i] - s.mean[i];
      s.standard_error[i] += d * d;
    }
  for (double& e : s.standard_error) e = std::sqrt(e / (r - 1) / r);
  return s;
}

SeriesSummary summarize(const std::vector<std::vector<double>>& rows) {
  if (rows.empty()) return {};
  for (const auto& row : rows)
    if (row.size() != rows[0].size()) throw InvalidInput("summarize: realizations have series of different lengths");
  return summarize(rows, 0, rows[0].size());
}

}  // namespace granular
