// A spreading run with k covariant Lyapunov vectors (SpreadingRunConfig::covariant_vectors): its CLVs
// are those of a direct covariant_vectors() call on the same orbit, the run's own curves do not change,
// and what cannot run is refused before it starts, naming the keyword.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "dynamics/dynamics_fixtures.hpp"
#include "granular/case/spreading_run.hpp"
#include "granular/chaos/covariant_vectors.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/error.hpp"
#include "granular/study/transport_study.hpp"

namespace granular {
namespace {

// The 8-bead chain of the spectrum tests: F0 = 0.01 N, kicked at 0.05 m/s, contacts opening.
struct CovariantRun {
  Chain chain = fixtures::anderson(8, 0.01);
  State start = velocity_kick(chain, 2, 0.05);
  SpreadingRunConfig config;
  CovariantRun() {
    config.integration.duration = 2e-4;  // 2000 steps of 0.1 µs
    config.integration.time_step = 1e-7;
    config.integration.window.enabled = false;
    config.integration.lyapunov.enabled = true;
    config.integration.lyapunov.renormalize_every = 7;
    config.spread.samples = 25;
    config.spread.site = 2;
  }
};

std::string covariant_refusal(const SpreadingRunConfig& c, std::size_t beads) {
  try {
    validate(c, beads);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(SpreadingCovariant, VectorsAreADirectRunsAndTheCurvesAreUnchanged) {
  CovariantRun s;
  const SpreadingResult plain = run_spreading(s.chain, s.start, s.config);
  EXPECT_TRUE(plain.covariant.time.empty());
  s.config.covariant_vectors = 4;  // transients: T/2 = 1000 steps each way
  const SpreadingResult r = run_spreading(s.chain, s.start, s.config);
  EXPECT_EQ(r.t, plain.t);
  EXPECT_EQ(r.m2, plain.m2);
  EXPECT_EQ(r.m2_centroid, plain.m2_centroid);
  EXPECT_EQ(r.ipr, plain.ipr);
  EXPECT_EQ(r.energy_error, plain.energy_error);
  EXPECT_EQ(r.mle, plain.mle);
  EXPECT_EQ(r.final_state.u, plain.final_state.u);
  EXPECT_EQ(r.final_state.v, plain.final_state.v);

  const CovariantVectorsConfig config = covariant_config(s.config);
  EXPECT_EQ(config.forward_transient, 1000u);
  EXPECT_EQ(config.backward_transient, 1000u);
  EXPECT_EQ(config.orthonormalize_every, 7u);
  const std::vector<std::uint64_t> steps = covariant_sample_steps(s.config);
  const CovariantVectors direct =
      covariant_vectors(make_force_law(ForceLawKind::hertz, s.chain), s.chain, saba2c(), 1e-7, s.start,
                        {.vectors = 4, .orthonormalize_every = 7, .forward_transient = 1000, .backward_transient = 1000},
                        steps);
  // The samples: the run's from T/2 on, the last at T.
  ASSERT_GE(direct.time.size(), 2u);
  std::size_t inside = 0;
  for (double t : r.t) inside += t >= 1e-4 * (1 - 1e-12);
  EXPECT_EQ(direct.time.size(), inside);
  EXPECT_EQ(r.covariant.time, direct.time);
  EXPECT_DOUBLE_EQ(direct.time.back(), r.t.back());
  EXPECT_EQ(r.covariant.growth_rates, direct.growth_rates);
  EXPECT_EQ(r.covariant.exponents, direct.exponents);
  EXPECT_EQ(r.covariant.split_angles, direct.split_angles);
  EXPECT_EQ(r.covariant.participation, direct.participation);
  EXPECT_EQ(r.covariant.centre, direct.centre);
  ASSERT_EQ(r.covariant.vectors.size(), direct.vectors.size());
  for (std::size_t i = 0; i < direct.vectors.size(); ++i)
    for (std::size_t j = 0; j < 4; ++j) {
      EXPECT_EQ(r.covariant.vectors[i][j].u, direct.vectors[i][j].u);
      EXPECT_EQ(r.covariant.vectors[i][j].v, direct.vectors[i][j].v);
    }
  // The CLVs' orbit is the run's to rounding: the forward transient is one advance, where the run stops at
  // each of its samples, and a splitting scheme's merged drifts round differently across a stop.
  const double du = fixtures::relative_difference(r.covariant.orbit.back().u, r.final_state.u),
               dv = fixtures::relative_difference(r.covariant.orbit.back().v, r.final_state.v);
  EXPECT_LT(du, 1e-12);
  EXPECT_LT(dv, 1e-12);
  std::printf("orbit at T against the run's: relative difference %.2g (u), %.2g (v)\n", du, dv);
}

TEST(SpreadingCovariant, RefusesWhatCannotRunBeforeItStarts) {
  CovariantRun s;
  s.config.covariant_vectors = 16;
  EXPECT_EQ(covariant_refusal(s.config, 8), "");
  s.config.covariant_vectors = 17;
  EXPECT_NE(covariant_refusal(s.config, 8).find("covariant_vectors 17: between 1 and 2N = 16"), std::string::npos)
      << covariant_refusal(s.config, 8);
  s.config.covariant_vectors = 4;
  s.config.integration.lyapunov.enabled = false;
  EXPECT_NE(covariant_refusal(s.config, 8).find("covariant_vectors: needs the Lyapunov"), std::string::npos);
  s.config.integration.lyapunov.enabled = true;
  s.config.covariant_transient = 3e-4;  // past T: no sample after it
  EXPECT_NE(covariant_refusal(s.config, 8).find("covariant_transient"), std::string::npos)
      << covariant_refusal(s.config, 8);
  s.config.covariant_transient = -1;
  EXPECT_NE(covariant_refusal(s.config, 8).find("covariant_transient"), std::string::npos);
  // 100 s of 0.1 µs: 1e9 steps, 1.4e8 packed R's of 136 doubles (~1.6e11 bytes), refused before a step.
  s.config.covariant_transient.reset();
  s.config.covariant_vectors = 16;
  s.config.integration.duration = 100;
  const std::string memory = covariant_refusal(s.config, 8);
  EXPECT_NE(memory.find("covariant_vectors 16: the stored factors and vectors need"), std::string::npos) << memory;
}

TEST(SpreadingCovariant, TheCaseNeedsOneRealization) {
  TransportCase c;
  c.chain.N = 8;
  c.realizations = 3;
  c.dynamics.integration.lyapunov.enabled = true;
  c.dynamics.covariant_vectors = 4;
  try {
    validate_before_time_step(c);
    ADD_FAILURE() << "an ensemble took the CLVs";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("covariant_vectors 4: one realization only"), std::string::npos) << e.what();
  }
  // The case JSON carries them, and reads back.
  c.realizations = 1;
  c.dynamics.covariant_transient = 3e-5;
  const TransportCase back = parse_case(describe(c));
  EXPECT_EQ(back.dynamics.covariant_vectors, 4u);
  EXPECT_EQ(back.dynamics.covariant_transient, 3e-5);
}

}  // namespace
}  // namespace granular
