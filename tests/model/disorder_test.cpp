#include "granular/model/disorder.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "granular/error.hpp"

namespace granular {
namespace {

TEST(Disorder, ParsesNamesAndRejectsOthers) {
  EXPECT_EQ(parse_disorder("h"), Disorder::homogeneous);
  EXPECT_EQ(parse_disorder("A"), Disorder::anderson);
  EXPECT_EQ(parse_disorder("rdm1"), Disorder::rdm1);
  EXPECT_EQ(parse_disorder("RDM2"), Disorder::rdm2);
  EXPECT_THROW(parse_disorder("RDM3"), InvalidInput);
  for (auto d : {Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2})
    EXPECT_EQ(parse_disorder(to_string(d)), d);
}

TEST(Disorder, RealizationIsAPureFunctionOfSeedAndIndex) {
  const auto a = realization_configuration(Disorder::anderson, 0.5, 500, 42, 17);
  const auto b = realization_configuration(Disorder::anderson, 0.5, 500, 42, 17);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, realization_configuration(Disorder::anderson, 0.5, 500, 42, 18));
  EXPECT_NE(a, realization_configuration(Disorder::anderson, 0.5, 500, 43, 17));
}

TEST(Disorder, AndersonFrequencyOfType1IsQ) {
  for (double q : {0.2, 0.5, 0.8}) {
    std::size_t ones = 0, total = 0;
    for (std::uint64_t r = 0; r < 40; ++r)
      for (auto t : realization_configuration(Disorder::anderson, q, 1000, 1, r)) {
        ones += t == 1;
        ++total;
      }
    const double p = static_cast<double>(ones) / static_cast<double>(total);
    const double sigma = std::sqrt(q * (1 - q) / static_cast<double>(total));
    EXPECT_NEAR(p, q, 5 * sigma) << "q = " << q;
  }
  for (auto t : realization_configuration(Disorder::anderson, 1.0, 100, 1, 0)) EXPECT_EQ(t, 1);
  for (auto t : realization_configuration(Disorder::anderson, 0.0, 100, 1, 0)) EXPECT_EQ(t, 2);
}

TEST(Disorder, DimersComeInPairsAndOddChainsDropTheLastBead) {
  for (std::size_t n : {100u, 101u}) {
    const auto rdm1 = realization_configuration(Disorder::rdm1, 0.5, n, 3, 0);
    const auto rdm2 = realization_configuration(Disorder::rdm2, 0.5, n, 3, 0);
    ASSERT_EQ(rdm1.size(), n);
    ASSERT_EQ(rdm2.size(), n);
    for (std::size_t i = 0; i + 1 < n; i += 2) {
      EXPECT_EQ(rdm1[i], rdm1[i + 1]);
      EXPECT_NE(rdm2[i], rdm2[i + 1]);
    }
    // The odd chain is the even chain's first N beads plus the first bead of one more dimer.
    if (n == 101) {
      const auto even = realization_configuration(Disorder::rdm1, 0.5, 102, 3, 0);
      EXPECT_TRUE(std::equal(rdm1.begin(), rdm1.end(), even.begin()));
    }
  }
  const auto all12 = realization_configuration(Disorder::rdm2, 1.0, 6, 1, 0);
  EXPECT_EQ(all12, (Configuration{1, 2, 1, 2, 1, 2}));
  const auto all21 = realization_configuration(Disorder::rdm2, 0.0, 6, 1, 0);
  EXPECT_EQ(all21, (Configuration{2, 1, 2, 1, 2, 1}));
}

TEST(Disorder, HomogeneousIsAllType1) {
  for (auto t : realization_configuration(Disorder::homogeneous, 0.3, 50, 1, 0)) EXPECT_EQ(t, 1);
}

TEST(Disorder, RadiiAndValidation) {
  EXPECT_EQ(radii_of({1, 2, 1}, 2.0, 0.25), (std::vector<double>{2.0, 0.5, 2.0}));
  EXPECT_THROW(radii_of({1, 2}, 1.0, 0.0), InvalidInput);
  EXPECT_THROW(radii_of({1, 2}, 1.0, 1.5), InvalidInput);
  EXPECT_THROW(realization_configuration(Disorder::anderson, 1.5, 10, 1, 0), InvalidInput);
  EXPECT_THROW(realization_configuration(Disorder::anderson, -0.1, 10, 1, 0), InvalidInput);
}

}  // namespace
}  // namespace granular
