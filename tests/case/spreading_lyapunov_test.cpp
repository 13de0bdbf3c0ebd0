// A spreading run with k deviation vectors (SpreadingRunConfig::lyapunov_vectors): its exponents
// are those of a direct LyapunovSpectrum run from the same state, its GALI and SALI those of
// AlignmentIndices from the same starting vectors, and the run's own curves do not change.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/dynamics_fixtures.hpp"
#include "granular/case/spreading_run.hpp"
#include "granular/chaos/alignment_indices.hpp"
#include "granular/chaos/lyapunov_spectrum.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/error.hpp"
#include "granular/study/transport_study.hpp"

namespace granular {
namespace {

// The 8-bead chain of the spectrum tests: F0 = 0.01 N, kicked at 0.05 m/s, contacts opening.
struct SmallRun {
  Chain chain = fixtures::anderson(8, 0.01);
  State start = velocity_kick(chain, 2, 0.05);
  SpreadingRunConfig config;
  SmallRun() {
    config.integration.duration = 2e-4;  // 2000 steps of 0.1 µs
    config.integration.time_step = 1e-7;
    config.integration.window.enabled = false;
    config.integration.lyapunov.enabled = true;
    config.integration.lyapunov.renormalize_every = 7;
    config.spread.samples = 25;
    config.spread.site = 2;
  }
};

std::string refusal(const SpreadingRunConfig& c, std::size_t beads) {
  try {
    validate(c, beads);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(SpreadingLyapunov, ExponentsAreADirectSpectrumRunsAndTheCurvesAreUnchanged) {
  SmallRun s;
  const SpreadingResult plain = run_spreading(s.chain, s.start, s.config);
  EXPECT_TRUE(plain.lyapunov.time.empty());
  s.config.lyapunov_vectors = 6;
  const SpreadingResult r = run_spreading(s.chain, s.start, s.config);

  // The run's own measurements, bit for bit.
  EXPECT_EQ(r.t, plain.t);
  EXPECT_EQ(r.m2, plain.m2);
  EXPECT_EQ(r.m2_centroid, plain.m2_centroid);
  EXPECT_EQ(r.ipr, plain.ipr);
  EXPECT_EQ(r.energy_error, plain.energy_error);
  EXPECT_EQ(r.mle, plain.mle);
  EXPECT_EQ(r.final_state.u, plain.final_state.u);
  EXPECT_EQ(r.final_state.v, plain.final_state.v);

  // A direct spectrum run advanced to the same sample times.
  const ForceLaw law = make_force_law(ForceLawKind::hertz, s.chain);
  LyapunovSpectrum direct(law, s.chain, saba2c(), 1e-7, s.start, {.vectors = 6, .orthonormalize_every = 7});
  ASSERT_EQ(r.lyapunov.time, r.t);
  ASSERT_EQ(r.lyapunov.exponents.size(), r.t.size());
  std::uint64_t done = 0;
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    const auto step = static_cast<std::uint64_t>(std::llround(r.t[i] / 1e-7));
    direct.advance(static_cast<std::size_t>(step - done));
    done = step;
    EXPECT_EQ(r.lyapunov.exponents[i], direct.exponents()) << "t = " << r.t[i];
  }
  // The spectrum's orbit is the run's (the tangent map's, whole chain, advanced by the same calls).
  EXPECT_EQ(direct.state().u, r.final_state.u);
  EXPECT_EQ(direct.state().v, r.final_state.v);
  // The orbit is chaotic: λ_1 > 0 at T, and the exponents come out largest first.
  const std::vector<double>& last = r.lyapunov.exponents.back();
  EXPECT_GT(last.front(), 1000.0);
  EXPECT_GT(last.front(), last.back());
}

TEST(SpreadingLyapunov, GaliAndSaliAreTheAlignmentIndicesOfTheSameStart) {
  SmallRun s;
  s.config.integration.duration = 5e-3;
  s.config.lyapunov_vectors = 4;
  const SpreadingResult r = run_spreading(s.chain, s.start, s.config);
  ASSERT_EQ(r.lyapunov.gali.size(), r.t.size());
  ASSERT_EQ(r.lyapunov.sali.size(), r.t.size());
  const std::vector<std::uint64_t> steps = sample_steps(s.config);
  const AlignmentSeries a = alignment_series(make_force_law(ForceLawKind::hertz, s.chain), s.chain, saba2c(), 1e-7,
                                             s.start, {.vectors = 4, .renormalize_every = 7}, steps);
  ASSERT_EQ(a.time, r.lyapunov.time);
  double worst = 0, smallest = 1;
  std::size_t compared = 0;
  for (std::size_t i = 0; i < a.time.size(); ++i) {
    ASSERT_EQ(r.lyapunov.gali[i].size(), 3u);
    for (std::size_t j = 0; j < 3; ++j) {
      const double want = a.gali[i][j], got = r.lyapunov.gali[i][j];
      smallest = std::min(smallest, got);
      if (want < 1e-9) continue;  // near AlignmentIndices' rounding floor its own digits go
      worst = std::max(worst, std::abs(got - want) / want);
      ++compared;
    }
    if (a.sali[i] >= 1e-9) worst = std::max(worst, std::abs(r.lyapunov.sali[i] - a.sali[i]) / a.sali[i]);
  }
  EXPECT_GT(compared, 40u);
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(smallest, 1e-3) << "a chaotic orbit: the vectors align";
  EXPECT_GT(r.lyapunov.gali.front().back(), 0.99) << "orthonormal at t = 0, one step before the first sample";
  std::printf("GALI_2..4 at T: %g %g %g, SALI %g; worst relative difference %g over %zu values\n",
              r.lyapunov.gali.back()[0], r.lyapunov.gali.back()[1], r.lyapunov.gali.back()[2], r.lyapunov.sali.back(),
              worst, compared);
}

TEST(SpreadingLyapunov, OneVectorGivesExponentsOnly) {
  SmallRun s;
  s.config.lyapunov_vectors = 1;
  const SpreadingResult r = run_spreading(s.chain, s.start, s.config);
  ASSERT_EQ(r.lyapunov.exponents.size(), r.t.size());
  EXPECT_EQ(r.lyapunov.exponents.back().size(), 1u);
  EXPECT_TRUE(r.lyapunov.gali.empty());
  EXPECT_TRUE(r.lyapunov.sali.empty());
}

TEST(SpreadingLyapunov, RefusesVectorsPastTwoNAndRunsTheTangentMapsRules) {
  SmallRun s;
  s.config.lyapunov_vectors = 16;
  EXPECT_EQ(refusal(s.config, 8), "");
  s.config.lyapunov_vectors = 17;
  EXPECT_NE(refusal(s.config, 8).find("lyapunov_vectors 17: between 1 and 2N = 16"), std::string::npos)
      << refusal(s.config, 8);
  s.config.lyapunov_vectors = 4;
  s.config.integration.lyapunov.enabled = false;
  EXPECT_NE(refusal(s.config, 8).find("lyapunov_vectors"), std::string::npos);
  s.config.integration.lyapunov.enabled = true;
  s.config.integration.damping.time = 1e-3;  // the tangent map's rule: conservative runs only
  EXPECT_NE(refusal(s.config, 8).find("lyapunov"), std::string::npos);
}

TEST(SpreadingLyapunov, TheCaseNeedsTheMapAndOneRealization) {
  const auto refused = [](auto set) {
    TransportCase c;
    c.chain.N = 8;
    c.realizations = 1;
    c.dynamics.lyapunov_vectors = 4;
    set(c);
    try {
      validate_before_time_step(c);
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refused([](TransportCase&) {}).find("lyapunov_vectors: takes effect only with `mle`"), std::string::npos)
      << refused([](TransportCase&) {});
  const std::string ensemble = refused([](TransportCase& c) {
    c.dynamics.integration.lyapunov.enabled = true;
    c.realizations = 3;
  });
  EXPECT_NE(ensemble.find("lyapunov_vectors 4: one realization only"), std::string::npos) << ensemble;
  EXPECT_EQ(refused([](TransportCase& c) { c.dynamics.integration.lyapunov.enabled = true; }), "");
  // The ensemble's own call refuses it even for one realization: its records hold no spectrum.
  TransportCase one;
  one.chain.N = 8;
  one.realizations = 1;
  one.dynamics.integration.duration = 1e-4;
  one.fit_begin = 2e-5, one.fit_end = 1e-4, one.fit_step = 1e-6;
  one.dynamics.integration.lyapunov.enabled = true;
  one.dynamics.lyapunov_vectors = 2;
  try {
    run_transport_study(one, {});
    ADD_FAILURE() << "an ensemble ran the spectrum";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("lyapunov_vectors 2: one realization only"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace granular
