// The observers and the driver (dynamics/observer.hpp, observers.hpp, spread.hpp): what an
// observer records is what the state says (m̃2, P⁻¹ and the energy error worked out here from the
// state by hand), a user-defined observer sees exactly the steps it asked for and the state at
// them, and observers never change the trajectory.
//
// What does enter the trajectory, at the rounding level, is where the driver stops: the splitting
// stepper merges the last drift (or corrector) of a step with the first of the next within one
// advance() (propagator.hpp), so stopping at a step to look splits a merged drift in two. Hence
// "bit for bit" below compares runs stopped at the same steps, and runs stopped at different
// steps agree to rounding.
#include "granular/dynamics/observers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics_fixtures.hpp"
#include "granular/dynamics/spread.hpp"
#include "granular/error.hpp"
#include "granular/model/contact_law.hpp"

namespace granular {
namespace {

/// Records every call: which steps, the state there, and finish().
struct Recorder : Observer {
  std::vector<std::uint64_t> wanted, seen;
  std::vector<double> times;
  std::vector<State> states;
  std::uint64_t finished_at = 0;
  int finished = 0;
  std::vector<std::uint64_t> schedule(const RunPlan&) override { return wanted; }
  void observe(const Snapshot& now) override {
    seen.push_back(now.step);
    times.push_back(now.t);
    states.push_back(now.state());
  }
  void finish(const Snapshot& at_T) override {
    finished_at = at_T.step;
    ++finished;
  }
};

TEST(Observers, EnergySpreadIsTheHandComputedSpreadOfTheState) {
  // The linear law, so E_n = m v²/2 + (B_n x_n² + B_{n+1} x_{n+1}²)/4 with B = (3/2) A^{2/3} F0^{1/3}
  // is a formula written out here, not the library's site_energies().
  const Chain chain = fixtures::anderson(81, 10.0);
  const std::size_t kicked = 30;
  const State initial = velocity_kick(chain, kicked, 8e-3);
  IntegrationConfig config{.duration = 2e-4, .time_step = 1e-6, .force_law = ForceLawKind::linear};
  EnergySpreadObserver spread({.samples = 5, .sampling = Sampling::uniform, .site = kicked});
  FinalStateObserver final_state;
  const RunInfo info = granular::spread(chain, initial, config, spread, final_state);
  ASSERT_DOUBLE_EQ(spread.t.back(), 2e-4);

  const std::size_t n = chain.size();
  const auto hand_energy = [&](const State& s, std::vector<double>& e) {
    const auto strain = [&](std::size_t k) { return (k > 0 ? s.u[k - 1] : 0.0) - (k < n ? s.u[k] : 0.0); };
    const auto phi = [&](std::size_t k) {
      return 0.5 * linear_stiffness(chain.contact[k], chain.precompression) * strain(k) * strain(k);
    };
    e.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) e[i] = 0.5 * chain.mass[i] * s.v[i] * s.v[i] + 0.5 * (phi(i) + phi(i + 1));
    return 0.5 * (phi(0) + phi(n));  // the wall halves no bead owns
  };
  std::vector<double> e0, e;
  const double walls0 = hand_energy(initial, e0);
  double h0 = walls0;
  for (double x : e0) h0 += x;
  const double walls = hand_energy(final_state.state, e);
  double total = 0, squares = 0, weighted = 0;
  for (std::size_t i = 0; i < n; ++i) total += e[i], squares += e[i] * e[i], weighted += static_cast<double>(i) * e[i];
  const double centroid = weighted / total;
  double about_site = 0, about_centroid = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double di = static_cast<double>(i);
    about_site += (di - static_cast<double>(kicked)) * (di - static_cast<double>(kicked)) * e[i];
    about_centroid += (di - centroid) * (di - centroid) * e[i];
  }
  std::printf("  m2 %.6f (centroid %.6f), P^-1 %.6f, energy error %.2e\n", about_site / total, about_centroid / total,
              squares / (total * total), spread.energy_error.back());
  EXPECT_NEAR(spread.m2.back(), about_site / total, 1e-12 * about_site / total);
  EXPECT_NEAR(spread.m2_centroid.back(), about_centroid / total, 1e-12 * about_centroid / total);
  EXPECT_NEAR(spread.ipr.back(), squares / (total * total), 1e-12);
  EXPECT_NEAR(info.initial_energy, h0, 1e-14 * h0);
  EXPECT_NEAR(spread.energy_error.back(), std::abs(total + walls - h0) / h0, 1e-13);
  EXPECT_GT(spread.m2.back(), 10.0) << "the energy did spread";
  EXPECT_EQ(spread.energy_error.front(), 0.0) << "t = 0 is the initial state";
}

TEST(Observers, AUserObserverSeesExactlyTheStepsItScheduled) {
  const Chain chain = fixtures::anderson(61, 1.0);
  const State initial = displacement_kick(chain, 30, 1e-7);
  const IntegrationConfig config{.duration = 50e-6, .time_step = 1e-6};
  Recorder recorder, other;
  recorder.wanted = {7, 0, 3, 7, 50, 99};  // unsorted, a duplicate, T itself, one past T
  other.wanted = {5, 6};
  const RunInfo info = granular::spread(chain, initial, config, recorder, other);
  EXPECT_EQ(recorder.seen, (std::vector<std::uint64_t>{0, 3, 7, 50}));
  EXPECT_EQ(other.seen, (std::vector<std::uint64_t>{5, 6}));
  EXPECT_EQ(recorder.finished, 1);
  EXPECT_EQ(recorder.finished_at, 50u);
  EXPECT_EQ(info.steps, 50u);
  // The state it saw is the propagator's after that many steps, bit for bit, when the propagator
  // stops where the driver did (0, 3, 5, 6, 7, 50).
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  auto p = make_splitting_propagator(law, chain, saba2c(), 1e-6, initial);
  std::size_t j = 0;
  for (std::uint64_t stop : {0, 3, 5, 6, 7, 50}) {
    p->advance(stop - p->steps_done());
    if (j < recorder.seen.size() && recorder.seen[j] == stop) {
      EXPECT_EQ(recorder.times[j], static_cast<double>(stop) * 1e-6);
      EXPECT_EQ(recorder.states[j].u, p->state().u) << "step " << stop;
      EXPECT_EQ(recorder.states[j].v, p->state().v) << "step " << stop;
      ++j;
    }
  }
  EXPECT_EQ(j, recorder.seen.size());
}

TEST(Observers, ObservingDoesNotChangeTheTrajectory) {
  const Chain chain = fixtures::anderson(201, 0.5);
  const State initial = velocity_kick(chain, 100, 8e-3);
  for (const Integrator& integrator : {Integrator(saba2c()), Integrator(srkn14a())}) {
    const IntegrationConfig config{.duration = 3e-4, .time_step = 1e-6, .integrator = integrator};
    FinalStateObserver watched;
    EnergySpreadObserver spread({.samples = 40, .dense = {1e-4, 3e-4, 3e-6}});
    ForceObserver forces({.sites = {90, 100, 110}, .samples = 77});
    EnergyMapObserver map({.samples = 31, .stride = 4});
    SpectralDensityObserver spectrum({.samples = 64});
    Recorder every;
    for (std::uint64_t s = 0; s <= 300; s += 13) every.wanted.push_back(s);
    const RunInfo info = granular::spread(chain, initial, config, spread, forces, map, spectrum, every, watched);
    EXPECT_EQ(map.columns, 51u);
    EXPECT_EQ(map.energy.size(), 31u * 51u);
    EXPECT_EQ(forces.t.size(), 77u);
    EXPECT_EQ(spectrum.density.size(), 64u / 2 + 1);
    EXPECT_EQ(every.seen, every.wanted);

    // The same stops, made by an observer that records but measures nothing: the same bits.
    // (schedule() starts each observer afresh, so their results are read above.)
    const RunPlan plan{chain.size(), 300, 1e-6, 3e-4};
    Recorder stops;
    for (Observer* o : std::initializer_list<Observer*>{&spread, &forces, &map, &spectrum, &every})
      for (std::uint64_t s : o->schedule(plan)) stops.wanted.push_back(s);
    FinalStateObserver bare;
    const RunInfo bare_info = granular::spread(chain, initial, config, stops, bare);
    EXPECT_EQ(watched.state.u, bare.state.u) << integrator.name();
    EXPECT_EQ(watched.state.v, bare.state.v) << integrator.name();
    EXPECT_EQ(info.bond_updates, bare_info.bond_updates);
    EXPECT_EQ(info.window_end, bare_info.window_end);

    // Without the stops: the propagator's own 300 steps taken at once, equal to rounding.
    const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
    auto p = make_propagator(integrator, law, chain, 1e-6, initial);
    p->advance(300);
    const double du = fixtures::relative_difference(bare.state.u, p->state().u);
    std::printf("  %s: %zu stops change the final u by %.1e relative\n", integrator.name().c_str(), stops.seen.size(),
                du);
    EXPECT_LT(du, 1e-12) << integrator.name();
  }
}

TEST(Observers, BadSettingsStopTheRunBeforeAnyStep) {
  const Chain chain = fixtures::anderson(41, 1.0);
  const State initial = displacement_kick(chain, 20, 1e-7);
  const IntegrationConfig config{.duration = 1e-5};
  Recorder recorder;
  recorder.wanted = {0, 1};
  ForceObserver forces({.sites = {41}});
  try {
    granular::spread(chain, initial, config, recorder, forces);
    FAIL() << "a force site outside the chain was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "forces_at") << e.what();
  }
  EXPECT_TRUE(recorder.seen.empty());
  EnergySpreadObserver spread({.samples = 1});
  EXPECT_THROW(granular::spread(chain, initial, config, spread), InvalidInput);
  EXPECT_THROW(granular::spread(chain, initial, {.duration = 1.5e-6}, recorder), InvalidInput);
}

// The energy map takes its whole memory when it is scheduled, before the first step: rows ×
// columns doubles (and the rows' times), so that a map that cannot be had fails then, not at its
// last sample hours in.
TEST(Observers, TheEnergyMapReservesItsMemoryBeforeTheRun) {
  EnergyMapObserver map({.samples = 1000, .stride = 3});
  const RunPlan plan{.beads = 1001, .total_steps = 5000, .time_step = 1e-7, .duration = 5e-4};
  const auto steps = map.schedule(plan);
  ASSERT_EQ(steps.size(), 1000u);
  EXPECT_EQ(map.columns, 334u);
  EXPECT_GE(map.energy.capacity(), 1000u * 334u);
  EXPECT_GE(map.t.capacity(), 1000u);
  EXPECT_EQ(map.settings().map_bytes(plan), 1000.0 * 334 * 8);
  // Fewer steps than samples: one row per step.
  EXPECT_EQ(map.settings().map_times({.beads = 1001, .total_steps = 99, .time_step = 1e-7, .duration = 9.9e-6}), 100);
}

TEST(Observers, TheEnergyGuardStopsOrRecords) {
  // τ = 10 µs is far too coarse for a 1e-6 m kick: the energy error passes 1e-6 early.
  const Chain chain = fixtures::anderson(101, 10.0);
  const State initial = displacement_kick(chain, 50, 1e-6);
  const IntegrationConfig config{.duration = 1e-3, .time_step = 1e-5};
  EnergySpreadObserver stop({.samples = 20, .max_energy_error = 1e-6});
  EXPECT_THROW(granular::spread(chain, initial, config, stop), NumericalError);
  EnergySpreadObserver warn({.samples = 20, .max_energy_error = 1e-6, .stop_on_energy_error = false});
  granular::spread(chain, initial, config, warn);
  EXPECT_GT(warn.max_energy_error, 1e-6);
  ASSERT_GE(warn.energy_guard_time, 0);
  const auto first = std::find_if(warn.energy_error.begin(), warn.energy_error.end(), [](double x) { return x > 1e-6; });
  EXPECT_EQ(warn.energy_guard_time, warn.t[static_cast<std::size_t>(first - warn.energy_error.begin())]);
}

TEST(Integrators, AreValuesParsedFromTheirNames) {
  EXPECT_EQ(parse_integrator("SABA2C").scheme.name, "saba2c");
  EXPECT_FALSE(parse_integrator("aba864").reference);
  EXPECT_EQ(parse_integrator("srkn14a").scheme.order, 6);
  const Integrator reference = parse_integrator("reference");
  EXPECT_TRUE(reference.reference);
  EXPECT_EQ(reference.name(), "reference");
  EXPECT_EQ(reference.tolerance.max_step, 0.01e-6);
  for (const char* name : {"saba2c", "saba2", "aba864", "srkn14a", "reference"})
    EXPECT_EQ(parse_integrator(name).name(), name);
  try {
    parse_integrator("rk4");
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "integrator");
  }
}

}  // namespace
}  // namespace granular
