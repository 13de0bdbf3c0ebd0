#include "granular/analysis/summary_statistics.hpp"

#include <algorithm>
#include <cmath>

#include "granular/error.hpp"

namespace granular {

SeriesSummary summarize(const std::vector<std::span<const double>>& rows) {
  SeriesSummary s;
  if (rows.empty()) return s;
  const std::size_t n = rows[0].size();
  for (const auto& row : rows)
    if (row.size() != n) throw InvalidInput("summarize: realizations have series of different lengths");
  const double r = static_cast<double>(rows.size());
  s.mean.assign(n, 0.0);
  s.standard_error.assign(n, 0.0);
  for (const auto& row : rows)
    for (std::size_t i = 0; i < n; ++i) s.mean[i] += row[i];
  for (double& m : s.mean) m /= r;
  if (rows.size() < 2) return s;
  for (const auto& row : rows)  // two passes: no cancellation from E[x²] − E[x]²
    for (std::size_t i = 0; i < n; ++i) {
      const double d = row[i] - s.mean[i];
      s.standard_error[i] += d * d;
    }
  for (double& e : s.standard_error) e = std::sqrt(e / (r - 1) / r);
  return s;
}

SeriesSummary summarize(const std::vector<std::vector<double>>& rows) {
  return summarize(std::vector<std::span<const double>>(rows.begin(), rows.end()));
}

}  // namespace granular
