// The centred draw: the beads around the centre are the same whatever N, dimers stay dimers on
// both sides, and the left and right halves are different draws with the model's statistics.
#include "granular/model/centred_configuration.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace granular {
namespace {

TEST(CentredConfiguration, TheBeadsAroundTheCentreDoNotDependOnN) {
  for (Disorder d : {Disorder::anderson, Disorder::rdm1, Disorder::rdm2})
    for (std::size_t n : {101u, 102u, 103u, 104u}) {
      const Configuration small = centred_configuration(d, 0.5, n, 7, 3);
      for (std::size_t big_n : {n + 1, n + 2, 3 * n / 2, 2 * n + 5}) {
        const Configuration big = centred_configuration(d, 0.5, big_n, 7, 3);
        const std::size_t c = (n - 1) / 2, big_c = (big_n - 1) / 2;
        ASSERT_EQ(small.size(), n);
        // Every bead of the small chain whose whole unit fits in it (a cut unit keeps its inner bead).
        for (std::size_t i = 1; i + 1 < n; ++i)
          ASSERT_EQ(small[i], big[i + big_c - c]) << to_string(d) << " N " << n << " vs " << big_n << " bead " << i;
      }
    }
}

TEST(CentredConfiguration, DimersStayDimersOnBothSides) {
  const std::size_t n = 2001, c = 1000;
  for (Disorder d : {Disorder::rdm1, Disorder::rdm2}) {
    const Configuration t = centred_configuration(d, 0.5, n, 1, 0);
    for (std::size_t i = c % 2; i + 1 < n; i += 2)  // units start at c ± 2j
      EXPECT_EQ(t[i] == t[i + 1], d == Disorder::rdm1) << to_string(d) << " beads " << i << ", " << i + 1;
  }
}

TEST(CentredConfiguration, BothHalvesCarryTheModelsStatistics) {
  const std::size_t n = 200001, c = 100000;
  for (double q : {0.2, 0.5}) {
    const Configuration t = centred_configuration(Disorder::anderson, q, n, 3, 1);
    double left = 0, right = 0, same = 0;
    for (std::size_t i = 0; i < c; ++i) {
      left += t[i] == 1;
      right += t[c + 1 + i] == 1;
      same += t[c - 1 - i] == t[c + 1 + i];  // mirror images: independent draws
    }
    const double sigma = std::sqrt(q * (1 - q) / static_cast<double>(c));
    EXPECT_NEAR(left / static_cast<double>(c), q, 5 * sigma);
    EXPECT_NEAR(right / static_cast<double>(c), q, 5 * sigma);
    EXPECT_NEAR(same / static_cast<double>(c), q * q + (1 - q) * (1 - q), 5 * 0.5 / std::sqrt(static_cast<double>(c)));
  }
}

TEST(CentredConfiguration, HomogeneousIsAllTypeOne) {
  for (auto t : centred_configuration(Disorder::homogeneous, 0.5, 11, 1, 0)) EXPECT_EQ(t, 1);
}

}  // namespace
}  // namespace granular
