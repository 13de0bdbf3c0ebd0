// The DKG exponents (klein_gordon/klein_gordon_exponents.hpp) and the slopes they are made of
// (analysis/power_law_fit.hpp): an exact power law's exponent, each realization's slope beside the
// mean curve's with its standard error, and refusals naming `fit`.
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "granular/analysis/power_law_fit.hpp"
#include "granular/error.hpp"
#include "granular/klein_gordon/klein_gordon_exponents.hpp"

namespace granular {
namespace {

// 41 log-spaced times from 1 to 10^6.
std::vector<double> kg_log_times() {
  std::vector<double> t;
  for (int k = 0; k <= 40; ++k) t.push_back(std::pow(10.0, 0.15 * k));
  return t;
}

std::vector<double> kg_power_law(const std::vector<double>& t, double a, double s) {
  std::vector<double> y;
  for (const double x : t) y.push_back(a * std::pow(x, s));
  return y;
}

TEST(KleinGordonExponents, LoglogSlopeOfAnExactPowerLawIsItsExponent) {
  const std::vector<double> t = kg_log_times();
  EXPECT_NEAR(loglog_slope(t, kg_power_law(t, 3, 0.37), 1e3, 1e5), 0.37, 1e-12);
  EXPECT_NEAR(loglog_slope(t, kg_power_law(t, 0.02, -0.3), 1, 1e6), -0.3, 1e-12);
  std::vector<double> v;  // 0.37 log10 t + 2: the same slope per decade
  for (const double x : t) v.push_back(0.37 * std::log10(x) + 2);
  EXPECT_NEAR(log_time_slope(t, v, 1e3, 1e5), 0.37, 1e-12);
  EXPECT_EQ(samples_inside(t, 1e3, 1e5), 14U);  // 10^(0.15 k) for k = 20 … 33
  std::vector<double> y = kg_power_law(t, 3, 0.37);
  y[25] = 0;  // t ≈ 5.6e3: a curve that touches 0 inside has no exponent
  EXPECT_TRUE(std::isnan(loglog_slope(t, y, 1e3, 1e5)));
  EXPECT_NEAR(loglog_slope(t, y, 1e4, 1e5), 0.37, 1e-12);        // outside the window it does not matter
  EXPECT_THROW(loglog_slope(t, y, 1.1e3, 1.2e3), InvalidInput);  // no sample inside
}

TEST(KleinGordonExponents, RealizationsSlopesBesideTheMeanCurvesWithTheirStandardError) {
  KleinGordonEnsemble e;
  e.time = kg_log_times();
  const double alphas[3] = {0.25, 0.33, 0.5};
  for (const double a : alphas) {
    KleinGordonRun run;
    run.time = e.time;
    run.m2 = kg_power_law(e.time, 2, a);
    run.participation = kg_power_law(e.time, 5, 0.2);  // the same in each: no spread
    run.mle = kg_power_law(e.time, 0.1, -0.25);
    e.runs.push_back(run);
  }
  e.m2.assign(e.time.size(), 0);
  e.participation = kg_power_law(e.time, 5, 0.2);
  e.mle = e.participation;  // not used: Λ's curve is ⟨log10 Λ⟩
  for (std::size_t s = 0; s < e.time.size(); ++s) {
    for (const KleinGordonRun& run : e.runs) e.m2[s] += run.m2[s] / 3;
    e.mean_log10_mle.push_back(std::log10(0.1) - 0.25 * std::log10(e.time[s]));
  }
  const KleinGordonExponents x = klein_gordon_exponents(e, 1e2, 1e5);
  EXPECT_EQ(x.samples, 20U);                                       // k = 14 … 33
  EXPECT_EQ(x.alpha.curve, loglog_slope(e.time, e.m2, 1e2, 1e5));  // the mean curve's: not the mean slope
  EXPECT_GT(x.alpha.curve, 0.4);
  EXPECT_NEAR(x.alpha.mean, (0.25 + 0.33 + 0.5) / 3, 1e-12);
  const double mean = (0.25 + 0.33 + 0.5) / 3;
  double var = 0;
  for (const double a : alphas) var += (a - mean) * (a - mean) / 2;
  EXPECT_NEAR(x.alpha.error, std::sqrt(var / 3), 1e-12);
  std::printf("  alpha = %.6f (mean curve), %.6f +- %.6f (realizations)\n", x.alpha.curve, x.alpha.mean, x.alpha.error);
  EXPECT_NEAR(x.alpha_P.curve, 0.2, 1e-12);
  EXPECT_NEAR(x.alpha_P.error, 0, 1e-12);
  EXPECT_NEAR(x.alpha_Lambda.curve, -0.25, 1e-12);
  EXPECT_NEAR(x.alpha_Lambda.mean, -0.25, 1e-12);

  const nlohmann::json j = describe(x, 3, true);
  EXPECT_EQ(j.at("fit"), nlohmann::json({1e2, 1e5}));
  EXPECT_EQ(j.at("alpha").get<double>(), x.alpha.curve);
  EXPECT_EQ(j.at("alpha_error").get<double>(), x.alpha.error);
  EXPECT_EQ(j.at("alpha_Lambda_mean").get<double>(), x.alpha_Lambda.mean);
  EXPECT_FALSE(describe(x, 1, false).contains("alpha_mean"));
  EXPECT_FALSE(describe(x, 1, false).contains("alpha_Lambda"));

  e.runs.resize(1);  // one realization: its slope, no spread
  const KleinGordonExponents one = klein_gordon_exponents(e, 1e2, 1e5);
  EXPECT_TRUE(std::isnan(one.alpha.mean) && std::isnan(one.alpha.error));
}

TEST(KleinGordonExponents, BadWindowsAreRefusedNamingFit) {
  KleinGordonEnsemble e;
  e.time = kg_log_times();
  e.m2 = e.participation = kg_power_law(e.time, 1, 0.3);
  KleinGordonRun run;  // without Λ
  run.time = e.time, run.m2 = e.m2, run.participation = e.participation;
  e.runs.push_back(run);
  for (const auto& [t0, t1] : std::vector<std::pair<double, double>>{{0, 10}, {10, 5}, {10, 10}, {1.1e3, 1.9e3}}) {
    try {
      klein_gordon_exponents(e, t0, t1);
      ADD_FAILURE() << t0 << ":" << t1 << " taken";
    } catch (const InvalidInput& error) {
      EXPECT_EQ(error.parameter(), "fit") << error.what();
    }
  }
}

}  // namespace
}  // namespace granular
