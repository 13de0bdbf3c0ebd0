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

// The dimers (beads 2j, 2j + 1) of a configuration: how many start with a type-1 bead, how many
// hold two different types.
struct DimerCount {
  double starting_with_one = 0;
  std::size_t unlike = 0;
};
DimerCount count_dimers(const Configuration& c) {
  DimerCount d;
  for (std::size_t j = 0; j + 1 < c.size(); j += 2) {
    d.starting_with_one += c[j] == 1;
    d.unlike += c[j] != c[j + 1];
  }
  return d;
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
    const DimerCount d = count_dimers(c);
    EXPECT_EQ(d.unlike, 0u) << "RDM1 dimers are only 11 or 22";
    expect_fraction(d.starting_with_one, beads / 2, q, "RDM1: fraction of 11 dimers");
  }
}

TEST(DisorderOrientation, Rdm2CountsOneTwoDimersAndHasNoLikePairInADimer) {
  for (double q : {0.2, 0.8}) {
    const Configuration c = realization_configuration(Disorder::rdm2, q, beads, 1, 0);
    const DimerCount d = count_dimers(c);
    EXPECT_EQ(d.unlike, beads / 2) << "RDM2 dimers are only 12 or 21";
    expect_fraction(d.starting_with_one, beads / 2, q, "RDM2: fraction of 12 dimers");
    // Hence no run of three like beads anywhere (any three consecutive beads hold a whole dimer).
    for (std::size_t i = 0; i + 2 < c.size(); ++i)
      ASSERT_FALSE(c[i] == c[i + 1] && c[i + 1] == c[i + 2]) << "three like beads at " << i;
  }
}

}  // namespace
}  // namespace granular
