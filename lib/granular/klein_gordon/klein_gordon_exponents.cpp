#include "granular/klein_gordon/klein_gordon_exponents.hpp"

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "granular/analysis/power_law_fit.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

// The slope of the mean curve beside the realizations' own slopes' mean ± std/√R (R ≥ 2).
KleinGordonSlope beside(double curve, const std::vector<double>& slopes) {
  KleinGordonSlope s;
  s.curve = curve;
  const std::size_t r = slopes.size();
  if (r < 2) return s;
  double mean = 0;
  for (const double x : slopes) mean += x;
  mean /= static_cast<double>(r);
  double var = 0;
  for (const double x : slopes) var += (x - mean) * (x - mean);
  s.mean = mean;
  s.error = std::sqrt(var / static_cast<double>(r - 1) / static_cast<double>(r));
  return s;
}

nlohmann::json number(double x) { return std::isnan(x) ? nlohmann::json(nullptr) : nlohmann::json(x); }

}  // namespace

KleinGordonExponents klein_gordon_exponents(const KleinGordonEnsemble& e, double t0, double t1) {
  std::string window = " ";  // appended, not `" " + a + ":" + b`: GCC 12 reports a false -Wrestrict
  window.append(format_number(t0)).append(":").append(format_number(t1));
  if (!(t0 > 0 && t0 < t1)) throw InvalidInput("fit", window + ": must satisfy 0 < t0 < t1");
  KleinGordonExponents x;
  x.begin = t0, x.end = t1;
  x.samples = samples_inside(e.time, t0, t1);
  if (x.samples < 3)
    throw InvalidInput("fit", window + ": holds " + std::to_string(x.samples) + " sample(s), need at least 3");
  std::vector<double> m2, p, lambda;
  for (const KleinGordonRun& run : e.runs) {
    m2.push_back(loglog_slope(run.time, run.m2, t0, t1));
    p.push_back(loglog_slope(run.time, run.participation, t0, t1));
    if (!run.mle.empty()) lambda.push_back(loglog_slope(run.time, run.mle, t0, t1));
  }
  x.alpha = beside(loglog_slope(e.time, e.m2, t0, t1), m2);
  x.alpha_P = beside(loglog_slope(e.time, e.participation, t0, t1), p);
  if (!e.mean_log10_mle.empty()) x.alpha_Lambda = beside(log_time_slope(e.time, e.mean_log10_mle, t0, t1), lambda);
  return x;
}

nlohmann::json describe(const KleinGordonExponents& x, std::size_t realizations, bool lambda) {
  nlohmann::json j;
  j["fit"] = {x.begin, x.end};
  j["samples"] = x.samples;
  const auto add = [&](const char* name, const KleinGordonSlope& s) {
    j[name] = number(s.curve);
    if (realizations < 2) return;
    j[std::string(name) + "_mean"] = number(s.mean);
    j[std::string(name) + "_error"] = number(s.error);
  };
  add("alpha", x.alpha);
  add("alpha_P", x.alpha_P);
  if (lambda) add("alpha_Lambda", x.alpha_Lambda);
  j["definition"] =
      "least-squares slopes over the samples in the window: alpha of log10 m2, alpha_P of log10 P, alpha_Lambda of "
      "<log10 Lambda>, against log10 t, of the mean curves; *_mean, *_error: each realization's own slope, "
      "their mean and standard error std/sqrt(R)";
  return j;
}

}  // namespace granular
