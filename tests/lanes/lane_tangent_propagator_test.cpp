// The tangent map in vector lanes (lanes/lane_tangent_propagator.hpp) against the one-chain
// TangentPropagator it must reproduce bit for bit: each lane's orbit, deviation vector and
// log-stretch, for every scheme, every force law, on-site springs linear and quartic, every
// renormalization interval, and batches with idle lanes; and a lane whose deviation vector fails
// alone.
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/dynamics_fixtures.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/error.hpp"
#include "granular/lanes/lane_tangent_propagator.hpp"
#include "lane_batch.hpp"

namespace granular {
namespace {

using fixtures::Batch;
using fixtures::granular_batch;

/// Deviation vectors spread over the chain: lane l's on bead (7 l + N/4) mod N, and a second
/// component so that δu and δv both start non-zero.
std::vector<State> spread_deviations(const Batch& b, double time_unit) {
  std::vector<State> out;
  for (std::size_t l = 0; l < b.chains.size(); ++l) {
    const std::size_t n = b.chains[l].size();
    State w = localized_deviation(n, (7 * l + n / 4) % n, time_unit);
    w.u[(7 * l + n / 2) % n] += 0.5;
    out.push_back(w);
  }
  return out;
}

/// Advances the lanes and each chain's TangentPropagator by the same pieces and asserts every
/// lane's u, v, δu, δv, log-stretch and bond count equal its chain's, bit for bit.
void expect_tangent_lanes_equal_alone(const Batch& b, const SplittingScheme& scheme, double tau,
                                      const LyapunovConfig& config, const std::string& what) {
  const std::vector<State> deviations = spread_deviations(b, config.time_unit);
  LaneTangentPropagator lanes(b.laws, b.chains, scheme, tau, b.initials, deviations, config);
  std::vector<std::unique_ptr<TangentPropagator>> alone;
  for (std::size_t l = 0; l < b.chains.size(); ++l)
    alone.push_back(make_tangent_propagator(b.laws[l], b.chains[l], scheme, tau, b.initials[l], deviations[l], config));
  std::vector<double> u, v, du, dv;
  for (const std::size_t steps : {1, 37, 200, 3}) {
    lanes.advance(steps);
    for (std::size_t l = 0; l < b.chains.size(); ++l) {
      try {
        alone[l]->advance(steps);
      } catch (const NumericalError& e) {
        ADD_FAILURE() << what << ", lane " << l << " alone, by step " << lanes.steps_done() << ": " << e.what();
        return;
      }
    }
    for (std::size_t l = 0; l < b.chains.size(); ++l) {
      const TangentPropagator& a = *alone[l];
      const std::string where = what + ", lane " + std::to_string(l) + ", step " + std::to_string(lanes.steps_done());
      lanes.copy_lane(l, u, v);
      lanes.copy_deviation(l, du, dv);
      const auto au = a.displacement(), av = a.velocity();
      const auto adu = a.deviation_displacement(), adv = a.deviation_velocity();
      EXPECT_EQ(u, std::vector<double>(au.begin(), au.end())) << where;
      EXPECT_EQ(v, std::vector<double>(av.begin(), av.end())) << where;
      EXPECT_EQ(du, std::vector<double>(adu.begin(), adu.end())) << where;
      EXPECT_EQ(dv, std::vector<double>(adv.begin(), adv.end())) << where;
      EXPECT_EQ(lanes.log_stretch(l), a.log_stretch()) << where;
      EXPECT_EQ(lanes.bond_updates(l), a.bond_updates()) << where;
      EXPECT_EQ(lanes.failure(l), "") << where;
    }
    if (::testing::Test::HasFailure()) return;  // one report, not one per later step
  }
}

TEST(LaneTangentPropagator, EveryLaneIsItsTangentMapAloneForEverySchemeAndLaw) {
  const std::size_t w = LaneTangentPropagator::width();
  for (const auto& scheme : {saba2c(), saba2(), aba864(), srkn14a()})
    for (const ForceLawKind kind : {ForceLawKind::hertz, ForceLawKind::fpu, ForceLawKind::linear}) {
      // Kicks, not a displaced chain: a contact that closes from a tiny overlap has an unbounded
      // curvature, where the scalar tangent map rightly stops too.
      const Batch b = granular_batch(w, 300, 10.0, kind, false);
      expect_tangent_lanes_equal_alone(b, scheme, 2e-7, {.enabled = true}, scheme.name + " " + to_string(kind));
    }
}

TEST(LaneTangentPropagator, EveryRenormalizationIntervalAndContactsThatOpen) {
  const std::size_t w = LaneTangentPropagator::width();
  const Batch b = granular_batch(w, 200, 1.0, ForceLawKind::hertz, false);
  for (const std::size_t every : {0, 1, 7, 10})
    expect_tangent_lanes_equal_alone(b, saba2c(), 2e-7, {.enabled = true, .renormalize_every = every},
                                     "every " + std::to_string(every));
  // F0 = 0: contacts open and close, where the curvature's floor keeps f'' finite.
  const Batch loose = granular_batch(w, 150, 0.0, ForceLawKind::hertz, false);
  expect_tangent_lanes_equal_alone(loose, saba2c(), 1e-7, {.enabled = true}, "F0 = 0");
}

TEST(LaneTangentPropagator, FewerChainsThanLanesLeaveTheOthersIdle) {
  for (std::size_t count = 1; count < LaneTangentPropagator::width(); ++count) {
    const Batch b = granular_batch(count, 120, 1.0, ForceLawKind::hertz, count == 2);
    expect_tangent_lanes_equal_alone(b, saba2c(), 2e-7, {.enabled = true}, std::to_string(count) + " chains");
  }
}

TEST(LaneTangentPropagator, OnsiteSpringsLinearAndQuartic) {
  const Batch springs = fixtures::s1_batch(LaneTangentPropagator::width());
  const Batch kg = fixtures::klein_gordon_batch(LaneTangentPropagator::width());
  expect_tangent_lanes_equal_alone(springs, saba2c(), 2e-7, {.enabled = true}, "on-site springs");
  // The Klein-Gordon tool's own settings: time unit 1, renormalized every 10 steps.
  expect_tangent_lanes_equal_alone(kg, saba2c(), 0.05, {.enabled = true, .renormalize_every = 10, .time_unit = 1},
                                   "Klein-Gordon");
  expect_tangent_lanes_equal_alone(kg, aba864(), 0.1, {.enabled = true, .renormalize_every = 10, .time_unit = 1},
                                   "Klein-Gordon ABA864");
}

TEST(LaneTangentPropagator, ALaneWhoseDeviationOverflowsFailsAloneAsItsTangentMapThrows) {
  const std::size_t w = LaneTangentPropagator::width();
  const Batch b = granular_batch(w, 100, 1.0, ForceLawKind::hertz, false);
  const LyapunovConfig config{.enabled = true, .renormalize_every = 1};
  std::vector<State> deviations = spread_deviations(b, config.time_unit);
  // Lane 1's vector is at the edge of the doubles: its norm overflows once it grows at all.
  for (double& x : deviations[1].u) x *= 8.5e153;
  for (double& x : deviations[1].v) x *= 8.5e153;
  auto alone = make_tangent_propagator(b.laws[1], b.chains[1], saba2c(), 2e-7, b.initials[1], deviations[1], config);
  std::size_t failed_at = 0;
  for (std::size_t step = 1; step <= 2000 && failed_at == 0; ++step) {
    try {
      alone->advance(1);
    } catch (const NumericalError&) {
      failed_at = step;
    }
  }
  ASSERT_GT(failed_at, 0u) << "the test needs a vector that overflows";
  LaneTangentPropagator lanes(b.laws, b.chains, saba2c(), 2e-7, b.initials, deviations, config);
  lanes.advance(failed_at - 1);
  EXPECT_EQ(lanes.failure(1), "");
  lanes.advance(1);
  EXPECT_EQ(lanes.failure(1), "tangent map: the deviation vector became non-finite");
  for (std::size_t l = 0; l < w; ++l) {
    if (l == 1) continue;
    EXPECT_EQ(lanes.failure(l), "") << "lane " << l;
    auto p = make_tangent_propagator(b.laws[l], b.chains[l], saba2c(), 2e-7, b.initials[l], deviations[l], config);
    p->advance(failed_at);
    EXPECT_EQ(lanes.log_stretch(l), p->log_stretch()) << "lane " << l;
  }
}

TEST(LaneTangentPropagator, RefusesAZeroDeviationOrOneVectorTooFew) {
  const Batch b = granular_batch(2, 100, 1.0, ForceLawKind::hertz, false);
  std::vector<State> deviations = spread_deviations(b, 1e-6);
  deviations[1] = State(100);
  EXPECT_THROW(LaneTangentPropagator(b.laws, b.chains, saba2c(), 1e-7, b.initials, deviations, {.enabled = true}),
               InvalidInput);
  deviations.pop_back();
  EXPECT_THROW(LaneTangentPropagator(b.laws, b.chains, saba2c(), 1e-7, b.initials, deviations, {.enabled = true}),
               InvalidInput);
}

}  // namespace
}  // namespace granular
