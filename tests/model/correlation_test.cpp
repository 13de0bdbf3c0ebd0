#include "granular/model/correlation.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "granular/model/material.hpp"
#include "granular/study/correlation_study.hpp"

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

// Masses are an affine function of the type indicator, and Pearson is invariant under affine maps:
// the coefficient of the masses of a two-type chain is the indicator's, to rounding.
TEST(Correlation, MassesOfTwoTypesGiveTheIndicatorsCoefficient) {
  for (Disorder kind : {Disorder::anderson, Disorder::rdm1, Disorder::rdm2}) {
    const Configuration types = realization_configuration(kind, 0.3, 501, 7, 2);
    std::vector<double> mass;
    for (auto t : types) mass.push_back(sphere_mass(steel, t == 1 ? 4.76e-3 : 2e-3));
    const auto by_type = cyclic_correlation(types, 20), by_mass = cyclic_value_correlation(mass, 20);
    for (std::size_t d = 0; d <= 20; ++d) EXPECT_NEAR(by_mass[d], by_type[d], 1e-13) << to_string(kind) << " d=" << d;
  }
  EXPECT_TRUE(std::isnan(cyclic_value_correlation({0.1, 0.1, 0.1}, 1)[1]));  // one kind of bead: undefined
  const auto three = cyclic_value_correlation({1, 2, 3, 1, 2, 3}, 3);        // period 3: ρ(3) = 1, ρ(1) = −½
  EXPECT_NEAR(three[0], 1, 1e-15);
  EXPECT_NEAR(three[1], -0.5, 1e-15);
  EXPECT_NEAR(three[3], 1, 1e-15);
}

// The study on k types and polydisperse radii against the infinite-chain formulas, and the
// two-type distribution against the paper's kinds (same chains, same coefficient to rounding).
TEST(Correlation, StudyOfBeadDistributions) {
  CorrelationConfig paper{.chain = {.source = TwoTypeDraw{.disorder = Disorder::rdm2, .q = 0.3}, .N = 400, .seed = 3},
                          .realizations = 50,
                          .max_distance = 5};
  CorrelationConfig two = paper;
  two.chain.source = BeadDistribution{.radii = {4.76e-3, 2.38e-3}, .probabilities = {0.3, 0.7}, .rule = Disorder::rdm2};
  const CorrelationResult a = correlation_study(paper), b = correlation_study(two);
  for (std::size_t d = 0; d <= 5; ++d) {
    EXPECT_NEAR(b.mean[d], a.mean[d], 1e-12) << d;
    EXPECT_NEAR(b.deviation[d], a.deviation[d], 1e-9) << d;
    EXPECT_DOUBLE_EQ(b.theory[d], a.theory[d]) << d;
  }
  const BeadDistribution three{.radii = {4.76e-3, 3e-3, 2e-3}, .probabilities = {0.5, 0.3, 0.2}};
  BeadDistribution uniform;
  uniform.kind = BeadDistribution::Kind::uniform;
  uniform.low = 2e-3;
  uniform.high = 5e-3;
  BeadDistribution dimers = three;
  dimers.rule = Disorder::rdm1;
  for (const BeadDistribution& beads : {three, uniform, dimers}) {
    CorrelationConfig c{.chain = {.source = beads, .N = 2000, .seed = 5}, .realizations = 200, .max_distance = 4};
    const CorrelationResult r = correlation_study(c, {.threads = 2});
    EXPECT_EQ(r.used, 200u);
    EXPECT_NEAR(r.mean[0], 1, 1e-14);
    for (std::size_t d = 1; d <= 4; ++d) {
      const double expected = beads.rule == Disorder::rdm1 && d == 1 ? 0.5 : 0.0;
      EXPECT_DOUBLE_EQ(r.theory[d], expected) << describe(beads) << " d=" << d;
      // 5 standard errors of the mean plus the O(1/N) bias of the finite ring
      EXPECT_NEAR(r.mean[d], expected, 5 * r.deviation[d] / std::sqrt(200.0) + 2.0 / 2000) << describe(beads);
    }
    const CorrelationResult one = correlation_study(c, {.threads = 1});
    EXPECT_EQ(one.mean, r.mean);  // bit for bit, any thread count
    EXPECT_EQ(one.deviation, r.deviation);
  }
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
