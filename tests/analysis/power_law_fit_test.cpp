#include "granular/analysis/power_law_fit.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "granular/analysis/log_derivative.hpp"
#include "granular/analysis/summary_statistics.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

std::vector<double> log_times(double t0, double t1, int count) {
  std::vector<double> t(count);
  for (int i = 0; i < count; ++i) t[i] = t0 * std::pow(t1 / t0, i / (count - 1.0));
  return t;
}

TEST(LogDerivative, ExactOnAPurePowerLaw) {
  const auto t = log_times(1e-5, 1e-2, 50);
  std::vector<double> y;
  for (double s : t) y.push_back(3.0 * std::pow(s, 1.37));
  const auto d = log_derivative(t, y);
  ASSERT_EQ(d.t.size(), 49u);
  for (double s : d.slope) EXPECT_NEAR(s, 1.37, 1e-12);
}

TEST(PowerLawFit, RecoversKnownExponentsFromNoisyData) {
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> noise(0.0, 0.02);  // 2 % multiplicative noise
  const auto t = log_times(1e-4, 1e-2, 200);
  for (double gamma : {0.5, 1.0, 1.5, 2.0}) {
    std::vector<double> y;
    for (double s : t) y.push_back(7e3 * std::pow(s, gamma) * std::exp(noise(rng)));
    const ExponentEstimate e = windowed_exponent(t, y, 4e-3, 1e-2);
    EXPECT_EQ(e.slopes.size(), 6u);
    // The 2 % noise over ~60 log-spaced points in a factor 2.5 of time moves a slope by ~0.05.
    EXPECT_NEAR(e.value, gamma, 0.06) << gamma;
    EXPECT_LT(e.error, 0.1);
  }
}

TEST(PowerLawFit, CriterionTakesLdOnConsecutiveSamples) {
  // docs/physics.md, "Nonlinear dynamics": L_d on the sampled times, not smoothed. On a 10 µs grid (Δ ln t ≈ 0.0025 at 4 ms) a
  // single sample 0.1 % off a pure power law moves the two L_d around it by ±0.001/0.0025 ≈ ±0.4:
  // the criterion must see it (a 0.1-in-ln t smoothing would have averaged it to ≈ 0.01).
  std::vector<double> t, y;
  for (int k = 0; k <= 600; ++k) {
    t.push_back(4e-3 + k * 1e-5);
    y.push_back(std::pow(t.back(), 1.3));
  }
  EXPECT_TRUE(judge_power_law(t, y, 1.3, {0.1, 4e-3}).power_law);
  y[300] *= 1.001;
  const PowerLawVerdict v = judge_power_law(t, y, 1.3, {0.1, 4e-3});
  EXPECT_FALSE(v.power_law);
  // The steps into and out of sample 300 (the one out is the larger, its Δ ln t being smaller).
  const double expected = std::log(1.001) / std::log(t[301] / t[300]);  // by hand
  EXPECT_NEAR(v.worst_deviation, expected, 0.01 * expected);
  EXPECT_NEAR(v.worst_time, std::sqrt(t[300] * t[301]), 1e-6 * t[300]);
  // t* is the start of the check, independent of the fit: starting after the glitch, no deviation.
  EXPECT_TRUE(judge_power_law(t, y, 1.3, {0.1, 7.1e-3}).power_law);
}

TEST(PowerLawFit, MeanLogDerivativeOfAPowerLawAndWindowEdges) {
  // Samples at k·1e-6 s: 4000·1e-6 may round either side of 4e-3, and the window includes it.
  std::vector<double> t, y;
  for (int k = 4000; k <= 10000; k += 10) {
    t.push_back(k * 1e-6);
    y.push_back(5 * std::pow(t.back(), -0.7));
  }
  EXPECT_NEAR(mean_log_derivative(t, y, 4e-3, 1e-2), -0.7, 1e-12);
  const ExponentEstimate m = windowed_mean_log_derivative(t, y, 4e-3, 1e-2);
  EXPECT_NEAR(m.value, -0.7, 1e-12);
  EXPECT_NEAR(m.error, 0.0, 1e-12);
  EXPECT_EQ(fit_power_law(t, y, 4e-3, 1e-2).points, t.size());
  EXPECT_EQ(fit_power_law(t, y, 5.5e-3, 8.5e-3).points, 301u);  // 5500 … 8500 µs every 10 µs
  EXPECT_THROW(mean_log_derivative(t, y, 4.001e-3, 4.009e-3), InvalidInput);
}

TEST(LogDerivative, MinimumLogStepPairsDistantSamples) {
  const std::vector<double> t{1, 1.05, 1.1, 1.2, 2.0}, y{1, 1.05, 1.1, 1.2, 2.0};
  const auto d = log_derivative(t, y, 0.1);
  ASSERT_EQ(d.t.size(), 4u);  // 1→1.2, 1.05→1.2, 1.1→2.0 (1.2/1.1 < e^0.1), 1.2→2.0
  for (double s : d.slope) EXPECT_NEAR(s, 1.0, 1e-12);
}

TEST(PowerLawFit, ExactWithoutNoiseIncludingDecay) {
  const auto t = log_times(1e-4, 1e-2, 100);
  std::vector<double> y;
  for (double s : t) y.push_back(std::pow(s, -0.8));
  const ExponentEstimate e = windowed_exponent(t, y, 4e-3, 1e-2);
  EXPECT_NEAR(e.value, -0.8, 1e-12);
  EXPECT_NEAR(e.error, 0.0, 1e-12);
  const PowerLawVerdict v = judge_power_law(t, y, e.value, {});
  EXPECT_TRUE(v.power_law);
  EXPECT_LT(v.worst_deviation, 1e-10);
}

TEST(PowerLawFit, FlagsLogPeriodicModulationAsNotAPowerLaw) {
  // y = t^1.5 (1 + 0.3 sin(2π ln t / ln 2)): the fitted mean slope is still ≈ 1.5, but L_d
  // oscillates by ±0.3·2π/ln 2 ≈ ±2.7 around it.
  const auto t = log_times(1e-4, 1e-2, 400);
  std::vector<double> y;
  for (double s : t)
    y.push_back(std::pow(s, 1.5) * (1 + 0.3 * std::sin(2 * std::numbers::pi * std::log(s) / std::log(2.0))));
  const ExponentEstimate e = windowed_exponent(t, y, 4e-3, 1e-2);
  const PowerLawVerdict v = judge_power_law(t, y, e.value, {0.1, 4e-3});
  EXPECT_FALSE(v.power_law);
  EXPECT_GT(v.worst_deviation, 1.0);
  EXPECT_GE(v.worst_time, 4e-3);
}

TEST(PowerLawFit, RejectsWindowsWithoutData) {
  const auto t = log_times(1e-4, 1e-3, 10);
  std::vector<double> y(t.size(), 1.0);
  EXPECT_THROW(windowed_exponent(t, y, 4e-3, 1e-2), InvalidInput);
  EXPECT_THROW(windowed_exponent(t, y, 1e-2, 4e-3), InvalidInput);
}

TEST(SummaryStatistics, StandardErrorShrinksLikeOneOverSqrtR) {
  // Synthetic realizations: value = 1 + unit Gaussian noise. The estimated standard error of the
  // mean must track σ/√R, so quadrupling R halves it (within the estimator's own scatter).
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  auto error_for = [&](std::size_t r) {
    std::vector<std::vector<double>> rows(r, std::vector<double>(1));
    for (auto& row : rows) row[0] = 1 + g(rng);
    return summarize(rows).standard_error[0];
  };
  for (std::size_t r : {100u, 400u, 1600u, 6400u}) {
    EXPECT_NEAR(error_for(r) * std::sqrt(static_cast<double>(r)), 1.0, 4.0 / std::sqrt(2.0 * static_cast<double>(r)) + 0.02)
        << "R = " << r;
  }
  EXPECT_NEAR(error_for(400) / error_for(1600), 2.0, 0.3);
  const auto one = summarize({{2.0, 3.0}});
  EXPECT_EQ(one.mean, (std::vector<double>{2.0, 3.0}));
  EXPECT_EQ(one.standard_error, (std::vector<double>{0.0, 0.0}));
}

}  // namespace
}  // namespace granular
