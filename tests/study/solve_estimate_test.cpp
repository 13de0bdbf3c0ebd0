// The estimate of a solve of every mode (solve_estimate.hpp): the larger block's time scaled by
// (N/(2·sample))^p with p fitted in [2, 3], and close enough to the real time that a power off by
// one (a factor 8 at N = 16·sample) shows.
#include "granular/study/solve_estimate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"

namespace granular {
namespace {

DynamicalMatrix solve_estimate_matrix(std::size_t n) {  // a random A chain at ξ = q = 0.5, F0 = 10 N
  const Configuration types = realization_configuration(Disorder::anderson, 0.5, n, 7, 0);
  return dynamical_matrix(make_chain(radii_of(types, 4.76e-3, 0.5), 10));
}

double solve_estimate_fastest_of_two(const DynamicalMatrix& d, const SpectrumConfig& config) {
  double best = 1e300;
  for (int i = 0; i < 2; ++i) {
    const auto start = std::chrono::steady_clock::now();
    (void)spectrum(d, all_modes(), config);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

TEST(SolveEstimate, TheBlockTimeScaledByTheFittedPower) {
  const DynamicalMatrix d = solve_estimate_matrix(2000);
  for (const SpectrumMethod method : {SpectrumMethod::lapack, SpectrumMethod::fast}) {
    SpectrumConfig config;
    config.method = method;
    const SolveEstimate e = estimate_every_mode_solve(d, config, all_modes(), 125);
    EXPECT_EQ(e.beads, 2000u);
    EXPECT_EQ(e.sample_beads, 250u);
    EXPECT_GE(e.power, 2);
    EXPECT_LE(e.power, 3);
    EXPECT_GT(e.sample_seconds, 0);
    // Not EXPECT_DOUBLE_EQ: clang rewrites pow(8.0, p) with a constant base as exp2(3p), which
    // differs from glibc's pow by up to 6 ulps (3 % of p in [2, 3] beyond the 4 that
    // EXPECT_DOUBLE_EQ allows: it failed CI's clang pass once); a power off by one is a factor 8.
    EXPECT_NEAR(e.seconds, e.sample_seconds * std::pow(8.0, e.power), 1e-14 * e.seconds);
    EXPECT_NE(describe(e).find("every mode of 2000 beads"), std::string::npos) << describe(e);
  }
}

TEST(SolveEstimate, NothingForSelectedModesOtherMethodsOrShortChains) {
  const DynamicalMatrix d = solve_estimate_matrix(2000);
  SpectrumConfig lapack;
  EXPECT_EQ(estimate_every_mode_solve(d, lapack, all_modes(), 251).seconds, 0);  // N < 8 sample
  EXPECT_EQ(estimate_every_mode_solve(d, lapack, all_modes(), 251).sample_beads, 0u);
  ModeSelection window;
  window.kind = ModeSelection::Kind::window;
  window.lo_khz = 1, window.hi_khz = 2;
  EXPECT_EQ(estimate_every_mode_solve(d, lapack, window, 250).seconds, 0);
  SpectrumConfig bisect;
  bisect.method = SpectrumMethod::bisect;
  EXPECT_EQ(estimate_every_mode_solve(d, bisect, all_modes(), 250).seconds, 0);
}

// The real solve of 8,000 beads against the estimate from its first 500 and 1,000 (the tool's
// blocks): within a factor 3 either way, where a power off by one would be a factor 8 away. Wall
// times on a shared machine: the fastest of two timings each, and blocks long enough (tens of ms)
// that a time slice lost to another process is not most of one. Long: ~15 s of solves. A timing
// check, so not part of the test command (timing stays out of the tests: under ctest -j2 with a
// threaded BLAS the 8,000-bead solve and the small blocks share the cores unevenly, and the ratio
// went past 3 once, 4.0 s estimated against 1.2 s); run it on an idle machine with
// GRANULAR_TIMING_TESTS=1 ctest -R SolveEstimate.
TEST(Long_SolveEstimate, PredictsTheRealTimeToWithinAFactorThree) {
  if (std::getenv("GRANULAR_TIMING_TESTS") == nullptr) GTEST_SKIP() << "a timing check: GRANULAR_TIMING_TESTS=1";
  const DynamicalMatrix d = solve_estimate_matrix(8000);
  for (const SpectrumMethod method : {SpectrumMethod::lapack, SpectrumMethod::fast}) {
    SpectrumConfig config;
    config.method = method;
    double estimate = 1e300;
    for (int i = 0; i < 2; ++i)
      estimate = std::min(estimate, estimate_every_mode_solve(d, config, all_modes()).seconds);
    const double real = solve_estimate_fastest_of_two(d, config);
    EXPECT_LT(estimate, 3 * real) << to_string(method);
    EXPECT_GT(estimate, real / 3) << to_string(method);
  }
}

}  // namespace
}  // namespace granular
