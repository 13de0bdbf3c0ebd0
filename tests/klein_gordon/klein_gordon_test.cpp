// The disordered Klein–Gordon chain as a Chain (klein_gordon/klein_gordon.hpp): ε̃ reproducible by seed
// bit for bit and inside [1/2, 3/2], the units (masses 1, bonds 1/W, quartic 1), and its checks.
#include "granular/klein_gordon/klein_gordon.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "granular/error.hpp"

namespace granular {
namespace {

TEST(KleinGordon, SameSeedGivesTheSameDisorderBitForBit) {
  const KleinGordonParameters p{.N = 4000, .W = 4, .seed = 7, .realization = 3};
  const std::vector<double> a = klein_gordon_disorder(p), b = klein_gordon(p).onsite;
  ASSERT_EQ(a.size(), p.N);
  EXPECT_EQ(a, b);  // operator== on doubles: bit for bit (no NaN can occur)
  EXPECT_EQ(a, klein_gordon_disorder(p));
  // Another seed or realization is another chain (a check that can fail).
  auto other_seed = p, other_realization = p;
  other_seed.seed = 8;
  other_realization.realization = 4;
  EXPECT_NE(a, klein_gordon_disorder(other_seed));
  EXPECT_NE(a, klein_gordon_disorder(other_realization));
  // W does not move the draws: the same ε̃ at any disorder strength.
  auto other_w = p;
  other_w.W = 10;
  EXPECT_EQ(a, klein_gordon_disorder(other_w));
}

TEST(KleinGordon, DisorderIsUniformInHalfToThreeHalves) {
  const std::vector<double> e = klein_gordon_disorder({.N = 100000, .W = 4, .seed = 1});
  double lo = e.front(), hi = e.front(), mean = 0, var = 0;
  for (double x : e) {
    lo = std::min(lo, x);
    hi = std::max(hi, x);
    mean += x;
  }
  mean /= static_cast<double>(e.size());
  for (double x : e) var += (x - mean) * (x - mean);
  var /= static_cast<double>(e.size() - 1);
  std::printf("  eps in [%.6f, %.6f], mean %.5f, variance %.5f (1/12 = %.5f)\n", lo, hi, mean, var, 1.0 / 12);
  EXPECT_GE(lo, 0.5);
  EXPECT_LE(hi, 1.5);
  EXPECT_LT(lo, 0.5 + 1e-3);  // the whole interval is used
  EXPECT_GT(hi, 1.5 - 1e-3);
  EXPECT_NEAR(mean, 1.0, 3e-3);  // 3 σ of the mean: σ = 0.29/√1e5 ≈ 9e-4
  EXPECT_NEAR(var, 1.0 / 12, 1e-3);
}

TEST(KleinGordon, ChainHasUnitMassesBondsOneOverWAndUnitQuartic) {
  const double w = 4;
  const Chain c = klein_gordon({.N = 10, .W = w, .seed = 2});
  ASSERT_EQ(c.size(), 10u);
  ASSERT_EQ(c.bonds(), 11u);
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_EQ(c.mass[i], 1.0);
    EXPECT_EQ(c.inverse_mass[i], 1.0);
    EXPECT_EQ(c.onsite_quartic[i], 1.0);
  }
  // Fixed ends: the walls hold the end sites by bonds 1/W like every other.
  for (double k : c.spring) EXPECT_EQ(k, 1 / w);
  EXPECT_EQ(linear_stiffness(c), c.spring);
  EXPECT_EQ(c.precompression, 0.0);
  const KleinGordonBand band = klein_gordon_band(w);
  EXPECT_EQ(band.omega2_min, 0.5);
  EXPECT_EQ(band.omega2_max, 2.5);
}

TEST(KleinGordon, RejectsParametersOutOfRange) {
  const auto field = [](const KleinGordonParameters& p) {
    try {
      klein_gordon(p);
    } catch (const InvalidInput& e) {
      return e.parameter();
    }
    return std::string("(none)");
  };
  EXPECT_EQ(field({.N = 1}), "N");
  EXPECT_EQ(field({.N = 10, .W = 0}), "W");
  EXPECT_EQ(field({.N = 10, .W = -1}), "W");
  EXPECT_EQ(field({.N = 10, .W = INFINITY}), "W");
  EXPECT_EQ(field({.N = 10, .W = NAN}), "W");
  EXPECT_EQ(field({.N = 10, .W = 4}), "(none)");
}

}  // namespace
}  // namespace granular
