// Chains side by side in vector lanes (dynamics/lane_propagator.hpp) against the one-chain
// propagator they must reproduce bit for bit: every scheme, every force law, on-site springs
// linear and quartic, windows that open at different beads and grow at different times, a lane
// whose window is the whole chain, and batches with idle lanes.
#include <cstddef>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics_fixtures.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/lane_propagator.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/error.hpp"
#include "granular/klein_gordon/klein_gordon.hpp"
#include "granular/model/material.hpp"
#include "granular/model/quasiperiodic.hpp"

namespace granular {
namespace {

struct Batch {
  std::vector<Chain> chains;
  std::vector<State> initials;
  std::vector<ForceLaw> laws;
};

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

/// Up to `count` Anderson chains of n beads, kicked at sites spread over the chain (so their windows
/// open apart), the last lane over the whole chain when `one_spread`.
Batch granular_batch(std::size_t count, std::size_t n, double f0, ForceLawKind kind, bool one_spread,
                     std::size_t site_step = 37) {
  Batch b;
  for (std::size_t l = 0; l < count; ++l) {
    b.chains.push_back(fixtures::anderson(n, f0, l));
    const std::size_t site = (l * site_step + n / 3) % n;
    if (one_spread && l + 1 == count) {  // every bead displaced: the window is the whole chain
      std::vector<double> shape(n);
      for (std::size_t i = 0; i < n; ++i) shape[i] = std::sin(0.3 * static_cast<double>(i + 1));
      b.initials.push_back(shaped_displacement(b.chains.back(), shape, 1e-8));
    } else {
      b.initials.push_back(velocity_kick(b.chains.back(), site, 0.01 * static_cast<double>(l + 1)));
    }
    b.laws.push_back(make_force_law(kind, b.chains.back()));
  }
  return b;
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
  const std::size_t w = LanePropagator::width();
  Batch springs, kg;
  for (std::size_t l = 0; l < w; ++l) {
    const Quasiperiodic q{.kind = Quasiperiodic::Kind::s1, .modulation = 0.7, .phase = 0.1 * static_cast<double>(l)};
    springs.chains.push_back(quasiperiodic_chain(q, 150, fixtures::r1, 10.0, steel, 0.4));
    springs.initials.push_back(velocity_kick(springs.chains.back(), 40 + 9 * l, 0.02));
    springs.laws.push_back(make_force_law(ForceLawKind::hertz, springs.chains.back()));
    kg.chains.push_back(klein_gordon({.N = 120, .W = 4, .seed = 3, .realization = l}));
    kg.initials.push_back(site_energy_kick(kg.chains.back(), 30 + 7 * l, 0.4));
    kg.laws.push_back(make_force_law(ForceLawKind::linear, kg.chains.back()));
  }
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
