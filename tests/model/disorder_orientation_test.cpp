// Which bead type the disorder probability q counts (docs/physics.md, "Disorder"), checked at q ≠ 1/2 where the two
// orientations differ: A counts type-1 beads, RDM1 "1 1" dimers, RDM2 "1 2" dimers; and the
// pairs RDM1 and RDM2 can never contain.
#include <cmath>

#include <gtest/gtest.h>

#include "granular/model/disorder.hpp"

namespace granular {
namespace {

constexpr std::size_t beads = 200000;  // 100000 dimers: the fraction's standard deviation ≈ 0.0013

// |fraction − q| within 5 binomial standard deviations of `draws` trials.
void expect_fraction(double count, double draws, double q, const char* what) {
  const double sigma = std::sqrt(q * (1 - q) / draws);
  EXPECT_NEAR(count / draws, q, 5 * sigma) << what;
}

TEST(DisorderOrientation, AndersonCountsTypeOneBeads) {
  for (double q : {0.2, 0.8}) {
    const Configuration c = realization_configuration(Disorder::anderson, q, beads, 1, 0);
    double ones = 0;
    for (auto t : c) ones += t == 1;
    expect_fraction(ones, beads, q, "A: fraction of type 1");
  }
}

TEST(DisorderOrientation, Rdm1CountsOneOneDimersAndNeverMixesADimer) {
  for (double q : {0.2, 0.8}) {
    const Configuration c = realization_configuration(Disorder::rdm1, q, beads, 1, 0);
    double ones = 0;
    for (std::size_t j = 0; j + 1 < c.size(); j += 2) {
      ASSERT_EQ(c[j], c[j + 1]) << "RDM1 dimer " << j / 2 << " is mixed";  // only 11 or 22
      ones += c[j] == 1;
    }
    expect_fraction(ones, beads / 2, q, "RDM1: fraction of 11 dimers");
  }
}

TEST(DisorderOrientation, Rdm2CountsOneTwoDimersAndHasNoLikePairInADimer) {
  for (double q : {0.2, 0.8}) {
    const Configuration c = realization_configuration(Disorder::rdm2, q, beads, 1, 0);
    double one_two = 0;
    for (std::size_t j = 0; j + 1 < c.size(); j += 2) {
      ASSERT_NE(c[j], c[j + 1]) << "RDM2 dimer " << j / 2 << " is 11 or 22";  // only 12 or 21
      one_two += c[j] == 1;
    }
    expect_fraction(one_two, beads / 2, q, "RDM2: fraction of 12 dimers");
    // Hence no run of three like beads anywhere (any three consecutive beads hold a whole dimer).
    for (std::size_t i = 0; i + 2 < c.size(); ++i)
      ASSERT_FALSE(c[i] == c[i + 1] && c[i + 1] == c[i + 2]) << "three like beads at " << i;
  }
}

}  // namespace
}  // namespace granular
