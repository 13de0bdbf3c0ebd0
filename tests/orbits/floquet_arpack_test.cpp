// The largest-modulus Floquet multipliers by ARPACK on the monodromy operator (orbits/floquet.hpp)
// against the dense monodromy matrix and dgeev on the same orbit: the gap breathers of a 101-bead
// diatomic chain, the heavy-centred family (unstable, a real pair) and the light-centred one
// (stable: every multiplier on the unit circle, the hard case for Arnoldi, which has no modulus
// gap to work with).
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "granular/linear/band_edges.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/orbits/breather_branch.hpp"
#include "granular/orbits/floquet.hpp"

namespace granular {
namespace {

// 101 beads alternating from `centre_type` (bead 51, the centre, is of that type), ξ = 0.5, seeded
// from the optical band's lowest mode and continued into the gap up to the first open contact.
struct GapBreather {
  Chain chain;
  ForceLaw law;
  PeriodicOrbit orbit;
};

GapBreather gap_breather(int centre_type, bool most_unstable) {
  const BandEdges edges = band_edges(steel, paper_r1, 0.5, 10);
  BreatherBranchConfig c;
  Configuration types(101);
  for (std::size_t i = 0; i < types.size(); ++i)
    types[i] = static_cast<std::uint8_t>(i % 2 == 0 ? centre_type : 3 - centre_type);
  c.chain.source = GivenTypes{.types = types, .xi = 0.5};
  const Chain chain = c.chain.chain(0);
  const Spectrum s = spectrum(dynamical_matrix(chain));
  long k = 0;
  while (s.freq_khz[static_cast<std::size_t>(k)] < (edges.fb1 + edges.fb2) / 2e3) ++k;
  c.mode = k + 1;
  c.max_points = 60;
  const auto branch = continue_breather(c);
  // The most unstable point with every contact closed, or the last such point (with a contact open
  // the +1 pair splits much further than √residual: docs/breathers.md).
  const BreatherPoint* p = nullptr;
  for (const auto& q : branch.points)
    if (q.max_open_fraction == 0 && (!p || !most_unstable || q.floquet.max_modulus > p->floquet.max_modulus)) p = &q;
  GapBreather out{chain, make_force_law(ForceLawKind::hertz, chain), {}};
  // The point's orbit again (Newton from the converged profile: no step needed).
  out.orbit = find_periodic_orbit(out.law, chain, p->omega, p->x0, {.steps_per_period = branch.steps_per_period});
  return out;
}

// Every ARPACK multiplier is one of dgeev's to 1e-8 (the pair at +1 aside: a Jordan block, which
// neither method resolves better than ~√ε), the largest modulus and the verdict are the same, and
// dgeev's multipliers off the unit circle (the +1 pair aside) are all among ARPACK's.
void expect_arpack_matches_dense(const GapBreather& b, bool stable) {
  const FloquetSpectrum dense =
      floquet_stability(b.law, b.chain, b.orbit, FloquetConfig{.method = FloquetMethod::dense});
  const FloquetSpectrum arpack =
      floquet_stability(b.law, b.chain, b.orbit, FloquetConfig{.method = FloquetMethod::arpack, .multipliers = 16});
  EXPECT_EQ(dense.method, "dense");
  EXPECT_EQ(arpack.method, "arpack");
  EXPECT_EQ(dense.multipliers.size(), 2 * b.chain.size());
  EXPECT_TRUE(arpack.complete);
  ASSERT_GE(arpack.multipliers.size(), 16u);
  EXPECT_EQ(dense.stable, stable);
  EXPECT_EQ(arpack.stable, dense.stable);
  EXPECT_EQ(arpack.instability, dense.instability);
  EXPECT_NEAR(arpack.max_modulus, dense.max_modulus, 1e-8);
  double worst = 0;
  for (const auto mu : arpack.multipliers) {
    if (std::abs(mu - 1.0) <= 1e-4) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto nu : dense.multipliers) nearest = std::min(nearest, std::abs(nu - mu));
    EXPECT_LT(nearest, 1e-8) << "ARPACK multiplier " << mu;
    worst = std::max(worst, nearest);
  }
  std::vector<std::complex<double>> by_distance = dense.multipliers;  // the +1 pair first
  std::sort(by_distance.begin(), by_distance.end(),
            [](auto a, auto b) { return std::abs(a - 1.0) < std::abs(b - 1.0); });
  for (const auto nu : std::vector(by_distance.begin() + 2, by_distance.end())) {
    if (std::abs(nu) <= 1 + 1e-3) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto mu : arpack.multipliers) nearest = std::min(nearest, std::abs(nu - mu));
    EXPECT_LT(nearest, 1e-8 * std::abs(nu)) << "dense multiplier " << nu << " missing";
  }
  // One rule on both sets (of the multipliers within the window of +1, the two nearest): what
  // ARPACK leaves out, dgeev leaves out too (here the pair is not among ARPACK's 16).
  const double window = FloquetConfig{}.unit_pair_window;
  const auto dense_pair = unit_pair(dense.multipliers, window);
  ASSERT_EQ(dense_pair.size(), 2u);
  for (std::size_t i : unit_pair(arpack.multipliers, window)) {
    bool left_out = false;
    for (std::size_t j : dense_pair)
      left_out = left_out || std::abs(dense.multipliers[j] - arpack.multipliers[i]) < 1e-6;
    EXPECT_TRUE(left_out) << "ARPACK leaves out " << arpack.multipliers[i];
  }
  // Every ARPACK multiplier's residual, measured by applying M to its Ritz vector again: the
  // check that fails when Arnoldi has lost accuracy (ARPACK's own estimate cannot see that).
  ASSERT_EQ(arpack.ritz_residuals.size(), arpack.multipliers.size());
  ASSERT_EQ(arpack.ritz_estimates.size(), arpack.multipliers.size());
  for (std::size_t i = 0; i < arpack.multipliers.size(); ++i) {
    EXPECT_LT(arpack.ritz_residuals[i], 1e-8) << arpack.multipliers[i];
    EXPECT_LT(arpack.ritz_estimates[i], 1e-10) << arpack.multipliers[i];  // dnaupd's: converged to 1e-12
  }
  EXPECT_EQ(arpack.ritz_residual, *std::max_element(arpack.ritz_residuals.begin(), arpack.ritz_residuals.end()));
  EXPECT_TRUE(dense.ritz_residuals.empty());
  EXPECT_TRUE(std::isnan(dense.ritz_residual));
  EXPECT_TRUE(std::isnan(arpack.reciprocal_error));
  EXPECT_TRUE(std::isnan(arpack.product_error));
  std::printf(
      "N = %zu: max|mu| dense %.12f arpack %.12f; worst distance to a dense multiplier %.2e; largest Ritz "
      "residual %.1e; %ld operator applications (dense: %ld), %d restarts\n",
      b.chain.size(), dense.max_modulus, arpack.max_modulus, worst, arpack.ritz_residual, arpack.operator_applications,
      dense.operator_applications, arpack.restarts);
}

TEST(FloquetArpack, LargestMultipliersOfAnUnstableGapBreatherAreTheDenseOnes) {
  const auto b = gap_breather(1, true);
  expect_arpack_matches_dense(b, false);
}

TEST(FloquetArpack, LargestMultipliersOfAStableGapBreatherAreTheDenseOnes) {
  const auto b = gap_breather(2, false);
  expect_arpack_matches_dense(b, true);
}

// An incomplete set is never called stable. The stable gap breather with too few restarts for
// every multiplier (every |mu| = 1: slow), some converged: complete = false, and the verdict is
// "unknown" rather than the "stable" its converged multipliers alone would give; the unstable one
// under the same starvation keeps its instability (a converged multiplier that grows is one).
// A Ritz residual limit below what was reached makes a converged set incomplete too.
TEST(FloquetArpack, AnIncompleteSetIsNeverCalledStable) {
  const auto stable = gap_breather(2, false);
  bool seen = false;
  for (int restarts : {100, 160}) {
    const FloquetConfig starved{.method = FloquetMethod::arpack, .max_restarts = restarts};
    const FloquetSpectrum s = try_largest_floquet_multipliers(stable.law, stable.chain, stable.orbit, starved);
    std::printf("%d restarts: %zu multipliers converged, complete %d, instability %s\n", restarts, s.multipliers.size(),
                s.complete ? 1 : 0, s.instability.c_str());
    if (s.multipliers.empty() || s.complete) continue;
    seen = true;
    EXPECT_LE(s.max_modulus, 1 + 1e-6) << restarts << " restarts";  // no growth among those converged
    EXPECT_FALSE(s.stable) << restarts << " restarts";
    EXPECT_EQ(s.instability, "unknown") << restarts << " restarts";
  }
  EXPECT_TRUE(seen) << "no restart count gave a partly converged set";
  const auto unstable = gap_breather(1, true);
  const FloquetSpectrum full =
      floquet_stability(unstable.law, unstable.chain, unstable.orbit, FloquetConfig{.method = FloquetMethod::arpack});
  ASSERT_TRUE(full.complete);
  ASSERT_FALSE(full.stable);
  FloquetConfig strict{.method = FloquetMethod::arpack};
  strict.ritz_residual_limit = full.ritz_residual / 2;
  const FloquetSpectrum doubted = floquet_stability(unstable.law, unstable.chain, unstable.orbit, strict);
  EXPECT_FALSE(doubted.complete);
  EXPECT_EQ(doubted.instability, full.instability);  // its growing multiplier still converged
  EXPECT_EQ(doubted.max_modulus, full.max_modulus);
}

TEST(FloquetArpack, AutomaticChoiceAndBadInput) {
  const auto b = gap_breather(2, false);
  const FloquetSpectrum small = floquet_stability(b.law, b.chain, b.orbit, FloquetConfig{.max_dense_beads = 101});
  EXPECT_EQ(small.method, "dense");
  // Beyond the dense limit and the fallback's: ARPACK alone.
  const FloquetSpectrum large =
      floquet_stability(b.law, b.chain, b.orbit, FloquetConfig{.max_dense_beads = 100, .max_fallback_beads = 100});
  EXPECT_EQ(large.method, "arpack");
  EXPECT_TRUE(large.complete);
  // Within the fallback's limit ARPACK gets the dense method's cost (2N = 202 applications), which
  // this stable orbit (every |mu| = 1) does not converge in (it takes ~3400): the dense multipliers
  // follow, the whole within about twice the dense cost (with 300 restarts: ~7000 applications).
  const FloquetSpectrum budget = floquet_stability(b.law, b.chain, b.orbit, FloquetConfig{.max_dense_beads = 100});
  EXPECT_EQ(budget.method.substr(0, 7), "dense (") << budget.method;
  EXPECT_EQ(budget.multipliers, small.multipliers);
  EXPECT_GT(budget.operator_applications, small.operator_applications) << "ARPACK was tried first";
  EXPECT_LE(budget.operator_applications, 2 * small.operator_applications + 40);
  for (int k : {0, 200, 202}) {
    try {
      floquet_stability(b.law, b.chain, b.orbit, FloquetConfig{.method = FloquetMethod::arpack, .multipliers = k});
      ADD_FAILURE() << "no exception for multipliers = " << k;
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.parameter(), "multipliers");
    }
  }
  try {
    floquet_stability(b.law, b.chain, b.orbit, FloquetConfig{.method = FloquetMethod::arpack, .subspace = 17});
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "subspace");
  }
  // A stable orbit where ARPACK gets one restart and converges nothing: automatic falls back to
  // the dense multipliers (up to max_fallback_beads), an explicit arpack request does not.
  const FloquetConfig starved{.max_dense_beads = 100, .max_restarts = 1};
  const FloquetSpectrum fallback = floquet_stability(b.law, b.chain, b.orbit, starved);
  EXPECT_EQ(fallback.method, "dense (ARPACK converged none)");
  ASSERT_EQ(fallback.multipliers.size(), small.multipliers.size());
  for (std::size_t i = 0; i < small.multipliers.size(); ++i) EXPECT_EQ(fallback.multipliers[i], small.multipliers[i]);
  EXPECT_EQ(fallback.stable, small.stable);
  FloquetConfig starved_arpack = starved;
  starved_arpack.method = FloquetMethod::arpack;
  EXPECT_THROW(floquet_stability(b.law, b.chain, b.orbit, starved_arpack), NumericalError);
  FloquetConfig starved_large = starved;
  starved_large.max_fallback_beads = 100;
  EXPECT_THROW(floquet_stability(b.law, b.chain, b.orbit, starved_large), NumericalError);
  EXPECT_EQ(parse_floquet_method("arpack"), FloquetMethod::arpack);
  EXPECT_EQ(to_string(FloquetMethod::automatic), "auto");
  EXPECT_THROW(parse_floquet_method("lapack"), InvalidInput);
}

}  // namespace
}  // namespace granular
