#include "granular/model/correlation.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace granular {
namespace {

TEST(Correlation, ExactOnPeriodicPatterns) {
  const auto alternating = cyclic_correlation({1, 2, 1, 2, 1, 2, 1, 2}, 3);
  EXPECT_DOUBLE_EQ(alternating[0], 1);
  EXPECT_DOUBLE_EQ(alternating[1], -1);
  EXPECT_DOUBLE_EQ(alternating[2], 1);
  EXPECT_TRUE(std::isnan(cyclic_correlation({1, 1, 1}, 1)[0]));  // one type: undefined
}

TEST(Correlation, TheoryLimits) {
  EXPECT_DOUBLE_EQ(correlation_theory(Disorder::rdm2, 0.5, 1), -0.5);
  EXPECT_DOUBLE_EQ(correlation_theory(Disorder::rdm2, 0.5, 2), 0.0);
  EXPECT_DOUBLE_EQ(correlation_theory(Disorder::rdm2, 1.0, 3), -1.0);
  EXPECT_DOUBLE_EQ(correlation_theory(Disorder::rdm2, 0.0, 4), 1.0);
  EXPECT_DOUBLE_EQ(correlation_theory(Disorder::rdm1, 0.3, 1), 0.5);
  EXPECT_DOUBLE_EQ(correlation_theory(Disorder::anderson, 0.3, 2), 0.0);
}

// Ensemble means against the infinite-chain formulas. The tolerance comes from the ensemble:
// 5 standard errors of the mean, plus the O(1/N) bias of a Pearson coefficient computed with
// the sample mean on a finite ring (|bias| ≲ 2/N for these short-range processes).
struct Case {
  Disorder kind;
  double q;
};
class CorrelationEnsemble : public ::testing::TestWithParam<Case> {};

TEST_P(CorrelationEnsemble, MeanMatchesTheory) {
  const auto [kind, q] = GetParam();
  const std::size_t n = 1000, realizations = 400, dmax = 6;
  std::vector<double> sum(dmax + 1), sum2(dmax + 1);
  for (std::size_t r = 0; r < realizations; ++r) {
    const auto rho = cyclic_correlation(realization_configuration(kind, q, n, 11, r), dmax);
    for (std::size_t d = 0; d <= dmax; ++d) {
      sum[d] += rho[d];
      sum2[d] += rho[d] * rho[d];
    }
  }
  const double rr = static_cast<double>(realizations);
  for (std::size_t d = 0; d <= dmax; ++d) {
    const double mean = sum[d] / rr;
    const double stderr_mean = std::sqrt(std::fmax(sum2[d] / rr - mean * mean, 0.0) / (rr - 1));
    const double tolerance = 5 * stderr_mean + 2.0 / static_cast<double>(n);
    EXPECT_NEAR(mean, correlation_theory(kind, q, d), tolerance) << to_string(kind) << " q=" << q << " d=" << d;
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, CorrelationEnsemble,
                         ::testing::Values(Case{Disorder::anderson, 0.5}, Case{Disorder::anderson, 0.8},
                                           Case{Disorder::rdm1, 0.5}, Case{Disorder::rdm1, 0.8},
                                           Case{Disorder::rdm2, 0.5}, Case{Disorder::rdm2, 0.8}),
                         [](const auto& info) {
                           return to_string(info.param.kind) + "_q" +
                                  std::to_string(static_cast<int>(info.param.q * 10));
                         });

}  // namespace
}  // namespace granular
