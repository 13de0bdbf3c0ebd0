// The DKG chain's library entry point (klein_gordon/klein_gordon_run.hpp): one realization from its
// (config, index) alone, and an ensemble whose means are bit-identical on 1 and 2 threads.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/error.hpp"
#include "granular/klein_gordon/klein_gordon_run.hpp"
#include "granular/lanes/lane_propagator.hpp"

namespace granular {
namespace {

// A 64-site chain at W = 4, a block of 21 sites at energy density 0.1 (random signs per
// realization), samples to t = 400 at τ = 0.2.
KleinGordonRunConfig kg_run_case() {
  return {.chain = {.N = 64, .W = 4, .seed = 7},
          .energy = 0.1,
          .block = 21,
          .time_step = 0.2,
          .sample_steps = {0, 50, 500, 2000}};
}

TEST(KleinGordonRun, EnsembleIsBitIdenticalOnOneAndTwoThreads) {
  const KleinGordonRunConfig c = kg_run_case();
  const KleinGordonEnsemble one = klein_gordon_ensemble(c, 8, 1);
  const KleinGordonEnsemble two = klein_gordon_ensemble(c, 8, 2);
  std::printf("  t = %.0f: <m2> = %.6f, <P> = %.6f, <Lambda> = %.6e, <log10 Lambda> = %.6f\n", one.time.back(),
              one.m2.back(), one.participation.back(), one.mle.back(), one.mean_log10_mle.back());
  EXPECT_EQ(one.time, two.time);
  EXPECT_EQ(one.m2, two.m2);
  EXPECT_EQ(one.participation, two.participation);
  EXPECT_EQ(one.mle, two.mle);
  // Λ(0) = 0 has no logarithm (NaN, which compares unequal to itself); the rest bit for bit.
  EXPECT_TRUE(std::isnan(one.mean_log10_mle[0]) && std::isnan(two.mean_log10_mle[0]));
  EXPECT_EQ(std::vector<double>(one.mean_log10_mle.begin() + 1, one.mean_log10_mle.end()),
            std::vector<double>(two.mean_log10_mle.begin() + 1, two.mean_log10_mle.end()));
  // Not trivially so: the realizations differ, and each is run_klein_gordon's for its index.
  EXPECT_NE(one.runs[0].m2.back(), one.runs[1].m2.back());
  EXPECT_NE(one.runs[0].mle.back(), one.runs[1].mle.back());
  double m2 = 0, lambda = 0;
  for (std::size_t r = 0; r < 8; ++r) {
    const KleinGordonRun alone = run_klein_gordon(c, r);
    EXPECT_EQ(alone.m2, two.runs[r].m2) << r;
    EXPECT_EQ(alone.mle, two.runs[r].mle) << r;
    m2 += alone.m2.back() / 8;
    lambda += alone.mle.back() / 8;
  }
  EXPECT_EQ(m2, two.m2.back());
  EXPECT_EQ(lambda, two.mle.back());
}

// An ensemble runs LanePropagator::width() realizations side by side in vector lanes (the rest one
// by one), with the mLE (each lane its deviation vector) or without: every run is run_klein_gordon's
// for its index, bit for bit, energy map and Λ(t) included, and so are the means on any thread count.
TEST(KleinGordonRun, AnEnsembleInLanesIsEachRealizationAloneBitForBit) {
  for (const bool mle : {false, true}) {
    KleinGordonRunConfig c = kg_run_case();
    c.mle = mle;
    c.energy_map = true;
    const std::size_t count = 2 * LanePropagator::width() + 3;
    const KleinGordonEnsemble one = klein_gordon_ensemble(c, count, 1), two = klein_gordon_ensemble(c, count, 2);
    EXPECT_EQ(one.m2, two.m2);
    EXPECT_EQ(one.participation, two.participation);
    EXPECT_EQ(one.mle, two.mle);
    for (std::size_t r = 0; r < count; ++r) {
      KleinGordonRunConfig alone_config = c;
      alone_config.energy_map = r == 0;  // an ensemble keeps realization 0's map only
      const KleinGordonRun alone = run_klein_gordon(alone_config, r);
      EXPECT_EQ(alone.time, two.runs[r].time) << r;
      EXPECT_EQ(alone.m2, two.runs[r].m2) << r;
      EXPECT_EQ(alone.participation, two.runs[r].participation) << r;
      EXPECT_EQ(alone.max_energy_error, two.runs[r].max_energy_error) << r;
      EXPECT_EQ(alone.energy_map, two.runs[r].energy_map) << r;
      EXPECT_EQ(alone.mle, two.runs[r].mle) << r;
      EXPECT_EQ(two.runs[r].mle.empty(), !mle);
    }
    EXPECT_NE(two.runs[0].m2.back(), two.runs[1].m2.back());
    if (mle) {
      EXPECT_NE(two.runs[0].mle.back(), two.runs[1].mle.back());
    }
  }
}

// The observables against their definitions from an independent plain run of the same
// realization: the tangent map's orbit is the plain run's bit for bit, so m2 and P are equal. At
// t = 0 a block of 21 equal site energies has P = 21 and, about its centroid (its middle site),
// m2 = Σ_{j=-10…10} j²/21 = 110/3.
TEST(KleinGordonRun, ObservablesAreThoseOfThePlainRun) {
  KleinGordonRunConfig c = kg_run_case();
  const KleinGordonRun with = run_klein_gordon(c, 3);
  c.mle = false;
  const KleinGordonRun without = run_klein_gordon(c, 3);
  EXPECT_TRUE(without.mle.empty());
  EXPECT_EQ(with.m2, without.m2);
  EXPECT_EQ(with.participation, without.participation);
  EXPECT_NEAR(with.participation.front(), 21, 1e-12);
  EXPECT_NEAR(with.m2.front(), 110.0 / 3.0, 1e-12);
  EXPECT_EQ(with.mle.front(), 0.0);
  EXPECT_LT(with.max_energy_error, 1e-4);
  // The same realization by hand: chain (seed 7, realization 3), the block centred on site 31.
  const Chain chain = klein_gordon({.N = 64, .W = 4, .seed = 7, .realization = 3});
  const ForceLaw law = make_force_law(ForceLawKind::linear, chain);
  auto p = make_splitting_propagator(law, chain, saba2c(), 0.2, block_energy_kick(chain, 21, 21, 0.1, 7, 3),
                                     {.enabled = false});
  p->advance(50);  // in the run's pieces: a stretch of steps merges its drifts, so pieces matter
  p->advance(450);
  p->advance(1500);
  const EnergySpread spread = energy_spread(site_energies(law, chain, p->state()), 31);
  EXPECT_EQ(with.m2.back(), spread.m2_centroid);
  EXPECT_EQ(with.participation.back(), 1 / spread.ipr);
}

// The energy map: realization 0's site energies at each sample, each row summing to H within the
// scheme's energy error, asked without changing the run; the other realizations keep none. On 128
// sites the energy does not reach the walls by t = 400, whose halves of the end bonds no site owns
// (observables.hpp: unowned_wall_energy): on kg_run_case's 64 sites they hold 4e-7 of H.
TEST(KleinGordonRun, EnergyMapRowsSumToTheEnergyWithinTheSchemesError) {
  KleinGordonRunConfig c = kg_run_case();
  c.chain.N = 128;
  c.energy_map = true;
  const KleinGordonEnsemble e = klein_gordon_ensemble(c, 3, 2);
  const KleinGordonRun& run = e.runs[0];
  const std::size_t n = 128, samples = run.time.size();
  ASSERT_EQ(run.energy_map.size(), samples * n);
  EXPECT_TRUE(e.runs[1].energy_map.empty() && e.runs[2].energy_map.empty());
  c.energy_map = false;
  const KleinGordonRun plain = run_klein_gordon(c, 0);
  EXPECT_TRUE(plain.energy_map.empty());
  EXPECT_EQ(plain.m2, run.m2);
  EXPECT_EQ(plain.mle, run.mle);
  const Chain chain = klein_gordon({.N = 128, .W = 4, .seed = 7, .realization = 0});
  const ForceLaw law = make_force_law(ForceLawKind::linear, chain);
  const double h0 = total_energy(law, chain, block_energy_kick(chain, 53, 21, 0.1, 7, 0));  // sites 53 … 73
  double worst = 0;
  for (std::size_t s = 0; s < samples; ++s) {
    const std::vector<double> row(run.energy_map.begin() + static_cast<std::ptrdiff_t>(s * n),
                                  run.energy_map.begin() + static_cast<std::ptrdiff_t>((s + 1) * n));
    double sum = 0;
    for (const double x : row) sum += x;
    worst = std::max(worst, std::abs(sum - h0) / h0);
    EXPECT_LE(std::abs(sum - h0) / h0, run.max_energy_error + 1e-13) << s;
    const EnergySpread spread = energy_spread(row, 63);  // the row is what m2 and P were made of
    EXPECT_EQ(spread.m2_centroid, run.m2[s]) << s;
  }
  std::printf("  H(0) = %.6f (21 sites at h = 0.1): rows off by at most %.2e, max_energy_error %.2e\n", h0, worst,
              run.max_energy_error);
}

TEST(KleinGordonRun, RefusesBadInput) {
  KleinGordonRunConfig c = kg_run_case();
  c.energy = 0;
  EXPECT_THROW(run_klein_gordon(c, 0), InvalidInput);
  c = kg_run_case();
  c.block = 65;
  EXPECT_THROW(run_klein_gordon(c, 0), InvalidInput);
  c = kg_run_case();
  c.sample_steps = {5, 4};
  EXPECT_THROW(run_klein_gordon(c, 0), InvalidInput);
  c.sample_steps = {};
  EXPECT_THROW(klein_gordon_ensemble(c, 2, 1), InvalidInput);
  c = kg_run_case();
  c.time_step = 0;
  EXPECT_THROW(run_klein_gordon(c, 0), InvalidInput);
  EXPECT_THROW(klein_gordon_ensemble(kg_run_case(), 0, 1), InvalidInput);
  c = kg_run_case();
  c.energy_map = true;
  c.chain.N = 100000000;
  c.sample_steps = {1, 2, 3};  // 3e8 values
  try {
    run_klein_gordon(c, 0);
    ADD_FAILURE() << "a map of 3e8 values taken";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "energy_map") << e.what();
  }
}

}  // namespace
}  // namespace granular
