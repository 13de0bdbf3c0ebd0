#include "granular/analysis/exponent_report.hpp"

namespace granular {

ExponentReport report_exponent(const std::vector<double>& t, const std::vector<double>& y, double lo, double hi,
                               const PowerLawCriterion& criterion) {
  ExponentReport r;
  r.fit = windowed_exponent(t, y, lo, hi);
  r.mean_ld = windowed_mean_log_derivative(t, y, lo, hi);
  r.verdict = judge_power_law(t, y, r.fit.value, criterion);
  return r;
}

}  // namespace granular
