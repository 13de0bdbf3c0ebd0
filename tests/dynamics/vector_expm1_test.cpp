#include "granular/dynamics/detail/vector_expm1.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

namespace {

using granular::detail::expm1_nonpositive;
using granular::detail::expm1_small_bound;
using granular::detail::expm1_small_nonpositive;
using granular::detail::expm1_unreduced_bound;
using granular::detail::expm1_unreduced_nonpositive;

// |value − exact| in units of the last place of `exact` rounded to double.
double ulps(double value, long double exact) {
  const double rounded = static_cast<double>(exact);
  const double ulp = std::nextafter(std::fabs(rounded), std::numeric_limits<double>::infinity()) - std::fabs(rounded);
  return static_cast<double>(std::fabs(static_cast<long double>(value) - exact) / ulp);
}

std::vector<double> arguments() {
  std::vector<double> x;
  for (double a = 1e-320; a < 800; a *= 1.0007) x.push_back(-a);      // tiny (subnormal) to past underflow
  for (int i = 0; i <= 200000; ++i) x.push_back(-40.0 * i / 200000);  // dense where the damping lives
  for (int k = -60; k <= 0; ++k)  // both sides of each range-reduction boundary (k + 1/2) ln 2
    for (double d : {-1e-12, 0.0, 1e-12}) x.push_back(std::min(0.0, (k + 0.5) * std::log(2.0) + d));
  return x;
}

TEST(VectorExpm1, WithinOneUlpOfTheExtendedPrecisionValue) {
  double worst = 0, worst_glibc = 0;
  for (double x : arguments()) {
    const long double exact = std::expm1l(static_cast<long double>(x));
    worst = std::max(worst, ulps(expm1_nonpositive(x), exact));
    worst_glibc = std::max(worst_glibc, ulps(std::expm1(x), exact));
  }
  EXPECT_LE(worst, 1.0) << "glibc's expm1: " << worst_glibc << " ulp";
}

TEST(VectorExpm1, ZerosInfinitiesAndNaN) {
  EXPECT_EQ(expm1_nonpositive(0.0), 0.0);
  EXPECT_TRUE(std::signbit(expm1_nonpositive(-0.0)));
  EXPECT_FALSE(std::signbit(expm1_nonpositive(0.0)));
  EXPECT_EQ(expm1_nonpositive(-std::numeric_limits<double>::infinity()), -1.0);
  EXPECT_EQ(expm1_nonpositive(-1e300), -1.0);
  EXPECT_EQ(expm1_nonpositive(1e300), 0.0);                // outside its domain, but defined (no integer overflow)
  EXPECT_EQ(expm1_nonpositive(-50.0), std::expm1(-50.0));  // −1 + 2e-22 rounds to −1
  EXPECT_TRUE(std::isnan(expm1_nonpositive(std::numeric_limits<double>::quiet_NaN())));
  const double tiny = -std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(expm1_nonpositive(tiny), tiny);  // no cancellation: e^x − 1 = x to the last bit
}

// The short series on its domain [−1/16, 0]: tiny (subnormal) to the bound, dense near it.
std::vector<double> small_arguments() {
  std::vector<double> x;
  for (double a = 1e-320; a <= -expm1_small_bound; a *= 1.0003) x.push_back(-a);
  for (int i = 0; i <= 200000; ++i) x.push_back(expm1_small_bound * i / 200000);
  return x;
}

TEST(VectorExpm1, ShortSeriesWithinOneUlpOnItsDomain) {
  double worst = 0;
  std::size_t same = 0;
  const std::vector<double> x = small_arguments();
  for (double a : x) {
    worst = std::max(worst, ulps(expm1_small_nonpositive(a), std::expm1l(static_cast<long double>(a))));
    same += expm1_small_nonpositive(a) == expm1_nonpositive(a);
  }
  std::printf("  short series: worst %.3f ulp; the same bits as the whole formula for %zu of %zu arguments\n", worst,
              same, x.size());
  EXPECT_LE(worst, 1.0);
  EXPECT_EQ(expm1_small_nonpositive(0.0), 0.0);
  EXPECT_TRUE(std::signbit(expm1_small_nonpositive(-0.0)));
}

// Without the range reduction where it is the identity: the whole formula's bits, every one.
TEST(VectorExpm1, UnreducedFormIsTheWholeFormulaBitForBit) {
  std::size_t differ = 0, count = 0;
  for (double a = 1e-320; a <= -expm1_unreduced_bound; a *= 1.0003, ++count)
    differ += expm1_unreduced_nonpositive(-a) != expm1_nonpositive(-a);
  for (int i = 0; i <= 200000; ++i, ++count) {
    const double x = expm1_unreduced_bound * i / 200000;
    differ += expm1_unreduced_nonpositive(x) != expm1_nonpositive(x);
  }
  EXPECT_EQ(differ, 0u) << "of " << count;
  EXPECT_TRUE(std::signbit(expm1_unreduced_nonpositive(-0.0)));
}

// The array form takes the short series only when every argument is in its domain, and is otherwise
// the whole formula element by element, bit for bit (NaN included), with or without the reduction.
TEST(VectorExpm1, ArrayFormChoosesThePathByItsWholeArgument) {
  std::vector<double> inside = {0.0, -1e-300, -1e-9, -0.01, expm1_small_bound};
  std::vector<double> outside = inside;
  outside.push_back(std::nextafter(expm1_small_bound, -1.0));
  std::vector<double> far = outside;
  far.push_back(std::nextafter(expm1_unreduced_bound, -1.0));
  std::vector<double> with_nan = inside;
  with_nan.push_back(std::numeric_limits<double>::quiet_NaN());
  std::vector<double> a = inside;
  expm1_nonpositive(a.data(), a.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], expm1_small_nonpositive(inside[i])) << i;
  for (const std::vector<double>& given : {outside, far, with_nan}) {
    a = given;
    expm1_nonpositive(a.data(), a.size());
    for (std::size_t i = 0; i + 1 < a.size(); ++i) EXPECT_EQ(a[i], expm1_nonpositive(given[i])) << i;
    EXPECT_EQ(std::isnan(a.back()), std::isnan(given.back()));
  }
}

}  // namespace
