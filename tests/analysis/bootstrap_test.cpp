// The realization bootstrap (analysis/bootstrap.hpp) against what it must estimate: the standard
// error of an ensemble exponent whose realizations have known exponents.
#include "granular/analysis/bootstrap.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "granular/analysis/power_law_fit.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

// R realizations y_r(t) = (t/t_c)^{γ_r} on the 10 µs grid of [4, 10] ms, γ_r = γ0 + s z_r with
// z_r standard normal; t_c = √(4·10) ms, the window's geometric centre, so that every realization
// weighs about equally in the mean and its exponent is ≈ the mean of the γ_r, whose standard error
// is s/√R.
struct Synthetic {
  std::vector<double> t, rows;
};
Synthetic power_laws(std::size_t realizations, double gamma0, double spread, std::uint64_t seed) {
  Synthetic s;
  for (int k = 0; k <= 600; ++k) s.t.push_back(4e-3 + k * 1e-5);
  const double centre = std::sqrt(4e-3 * 1e-2);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> z(0.0, 1.0);
  for (std::size_t r = 0; r < realizations; ++r) {
    const double gamma = gamma0 + spread * z(rng);
    for (double t : s.t) s.rows.push_back(std::pow(t / centre, gamma));
  }
  return s;
}

std::vector<double> exponent_of_mean(const std::vector<double>& t, const std::vector<double>& mean) {
  return {windowed_exponent(t, mean, 4e-3, 1e-2).value, mean_log_derivative(t, mean, 4e-3, 1e-2)};
}

TEST(Bootstrap, ErrorOfTheEnsembleExponentIsSpreadOverRootR) {
  for (auto [realizations, spread] : {std::pair<std::size_t, double>{400, 0.1}, {100, 0.3}, {1000, 0.05}}) {
    const Synthetic s = power_laws(realizations, 1.5, spread, 11 + realizations);
    const auto sd =
        bootstrap_standard_deviation(s.rows, s.t.size(),
                                     [&](const std::vector<double>& mean) { return exponent_of_mean(s.t, mean); }, {});
    const double analytic = spread / std::sqrt(static_cast<double>(realizations));
    EXPECT_NEAR(sd[0], analytic, 0.2 * analytic) << "R = " << realizations << ", s = " << spread;
    EXPECT_NEAR(sd[1], analytic, 0.2 * analytic) << "mean L_d, R = " << realizations;
  }
}

TEST(Bootstrap, SameAnswerForAnyThreadCountAndNothingToResampleFromOneRealization) {
  const Synthetic s = power_laws(50, 1.2, 0.2, 3);
  const auto statistic = [&](const std::vector<double>& mean) { return exponent_of_mean(s.t, mean); };
  BootstrapConfig one, two;
  one.threads = 1;
  two.threads = 2;
  EXPECT_EQ(bootstrap_standard_deviation(s.rows, s.t.size(), statistic, one),
            bootstrap_standard_deviation(s.rows, s.t.size(), statistic, two));
  BootstrapConfig other = one;
  other.seed = 99;  // another seed: another set of resamples, a slightly different estimate
  EXPECT_NE(bootstrap_standard_deviation(s.rows, s.t.size(), statistic, one),
            bootstrap_standard_deviation(s.rows, s.t.size(), statistic, other));
  const std::vector<double> single(s.rows.begin(), s.rows.begin() + static_cast<long>(s.t.size()));
  EXPECT_EQ(bootstrap_standard_deviation(single, s.t.size(), statistic, one), (std::vector<double>{0.0, 0.0}));
}

TEST(Bootstrap, RejectsRaggedInputAndPassesOnAFailingStatistic) {
  const std::vector<double> rows(10, 1.0);
  const auto ok = [](const std::vector<double>& m) { return m; };
  EXPECT_THROW(bootstrap_standard_deviation(rows, 3, ok, {}), InvalidInput);
  EXPECT_THROW(bootstrap_standard_deviation({}, 3, ok, {}), InvalidInput);
  BootstrapConfig few;
  few.resamples = 1;
  EXPECT_THROW(bootstrap_standard_deviation(rows, 5, ok, few), InvalidInput);
  const auto failing = [](const std::vector<double>&) -> std::vector<double> { throw std::runtime_error("boom"); };
  EXPECT_THROW(bootstrap_standard_deviation(rows, 5, failing, {}), std::runtime_error);
}

}  // namespace
}  // namespace granular
