// Chains side by side in vector lanes (lanes/lane_propagator.hpp) against the one-chain
// propagator they must reproduce bit for bit: every scheme, every force law, on-site springs
// linear and quartic, windows that open at different beads and grow at different times, a lane
// whose window is the whole chain, and batches with idle lanes.
#include <cstddef>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/dynamics_fixtures.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/error.hpp"
#include "granular/lanes/lane_propagator.hpp"
#include "lane_batch.hpp"

namespace granular {
namespace {

using fixtures::Batch;
using fixtures::granular_batch;

/// Advances the lanes and each chain alone by the same pieces (so that merged correctors and
/// window growth between calls are covered) and asserts every lane's state, window and bond count
/// equal its chain's, bit for bit. Returns whether some lane's window grew.
bool expect_lanes_equal_alone(const Batch& b, const SplittingScheme& scheme, double tau, const ActiveWindow& window,
                              const std::string& what) {
  LanePropagator lanes(b.laws, b.chains, scheme, tau, b.initials, window);
  std::vector<std::unique_ptr<Propagator>> alone;
  for (std::size_t l = 0; l < b.chains.size(); ++l)
    alone.push_back(make_splitting_propagator(b.laws[l], b.chains[l], scheme, tau, b.initials[l], window));
  std::vector<double> u, v;
  std::vector<std::size_t> opened;
  for (std::size_t l = 0; l < b.chains.size(); ++l) opened.push_back(lanes.window_end(l) - lanes.window_begin(l));
  for (const std::size_t steps : {1, 37, 200, 1}) {
    lanes.advance(steps);
    for (auto& p : alone) p->advance(steps);
    for (std::size_t l = 0; l < b.chains.size(); ++l) {
      lanes.copy_lane(l, u, v);
      const auto au = alone[l]->displacement(), av = alone[l]->velocity();
      EXPECT_EQ(u, std::vector<double>(au.begin(), au.end()))
          << what << ", lane " << l << ", step " << lanes.steps_done();
      EXPECT_EQ(v, std::vector<double>(av.begin(), av.end()))
          << what << ", lane " << l << ", step " << lanes.steps_done();
      EXPECT_EQ(lanes.window_begin(l), alone[l]->window_begin()) << what << ", lane " << l;
      EXPECT_EQ(lanes.window_end(l), alone[l]->window_end()) << what << ", lane " << l;
      EXPECT_EQ(lanes.bond_updates(l), alone[l]->bond_updates()) << what << ", lane " << l;
    }
    if (::testing::Test::HasFailure()) return false;  // one report, not one per later step
  }
  for (std::size_t l = 0; l < b.chains.size(); ++l)
    if (lanes.window_end(l) - lanes.window_begin(l) != opened[l]) return true;
  return false;
}

TEST(LanePropagator, EveryLaneIsItsChainAloneForEverySchemeAndLaw) {
  const std::size_t w = LanePropagator::width();
  for (const auto& scheme : {saba2c(), saba2(), aba864(), srkn14a()})
    for (const ForceLawKind kind : {ForceLawKind::hertz, ForceLawKind::fpu, ForceLawKind::linear}) {
      const Batch b = granular_batch(w, 400, 1.0, kind, true);
      expect_lanes_equal_alone(b, scheme, 2e-7, {}, scheme.name + " " + to_string(kind));
    }
}

TEST(LanePropagator, WindowsOffAndWindowsThatGrowAtDifferentTimes) {
  const std::size_t w = LanePropagator::width();
  const Batch b = granular_batch(w, 600, 0.1, ForceLawKind::hertz, false);
  expect_lanes_equal_alone(b, saba2c(), 2e-7, {.enabled = false}, "window off");
  EXPECT_TRUE(expect_lanes_equal_alone(b, saba2c(), 2e-7, {.enabled = true, .threshold = 1e-30, .guard = 8}, "guard 8"));
  // Kicked near one site (an ensemble's way): the lanes' window edges are checked together.
  const Batch near = granular_batch(w, 600, 0.1, ForceLawKind::hertz, false, 3);
  EXPECT_TRUE(expect_lanes_equal_alone(near, saba2c(), 2e-7, {.enabled = true, .threshold = 1e-30, .guard = 8},
                                       "near, guard 8"));
  expect_lanes_equal_alone(near, saba2c(), 2e-7, {}, "near");
  // Sound kicks that separate beads (F0 = 0: no precompression, contacts open and close).
  const Batch loose = granular_batch(w, 300, 0.0, ForceLawKind::hertz, false);
  expect_lanes_equal_alone(loose, saba2c(), 1e-7, {}, "F0 = 0");
}

TEST(LanePropagator, FewerChainsThanLanesLeaveTheOthersIdle) {
  for (std::size_t count = 1; count < LanePropagator::width(); ++count) {
    const Batch b = granular_batch(count, 200, 1.0, ForceLawKind::hertz, count == 2);
    expect_lanes_equal_alone(b, saba2c(), 2e-7, {}, std::to_string(count) + " chains");
  }
}

TEST(LanePropagator, OnsiteSpringsLinearAndQuartic) {
  const Batch springs = fixtures::s1_batch(LanePropagator::width());
  const Batch kg = fixtures::klein_gordon_batch(LanePropagator::width());
  expect_lanes_equal_alone(springs, saba2c(), 2e-7, {}, "on-site springs");
  expect_lanes_equal_alone(kg, saba2c(), 0.05, {}, "Klein-Gordon");
  expect_lanes_equal_alone(kg, aba864(), 0.1, {}, "Klein-Gordon ABA864");
}

TEST(LanePropagator, RefusesChainsOfOtherLengthsOrLawsOfOtherKinds) {
  Batch b = granular_batch(2, 100, 1.0, ForceLawKind::hertz, false);
  b.chains[1] = fixtures::anderson(101, 1.0, 1);
  b.initials[1] = velocity_kick(b.chains[1], 50, 0.01);
  b.laws[1] = make_force_law(ForceLawKind::hertz, b.chains[1]);
  EXPECT_THROW(LanePropagator(b.laws, b.chains, saba2c(), 1e-7, b.initials), InvalidInput);
  Batch mixed = granular_batch(2, 100, 1.0, ForceLawKind::hertz, false);
  mixed.laws[1] = make_force_law(ForceLawKind::fpu, mixed.chains[1]);
  EXPECT_THROW(LanePropagator(mixed.laws, mixed.chains, saba2c(), 1e-7, mixed.initials), InvalidInput);
  const Batch too_many = granular_batch(LanePropagator::width() + 1, 50, 1.0, ForceLawKind::hertz, false);
  EXPECT_THROW(LanePropagator(too_many.laws, too_many.chains, saba2c(), 1e-7, too_many.initials), InvalidInput);
}

}  // namespace
}  // namespace granular
