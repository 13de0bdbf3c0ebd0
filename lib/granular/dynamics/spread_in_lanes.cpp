// The driver of spread.cpp over a LanePropagator: the same schedule, the same snapshots, per lane.
#include "granular/dynamics/spread_in_lanes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <tuple>

#include "granular/dynamics/detail/observation_events.hpp"
#include "granular/dynamics/lane_propagator.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/error.hpp"

namespace granular {

bool runs_in_lanes(const IntegrationConfig& config) {
  return !config.integrator.reference && !config.damping.any() && !config.lyapunov.enabled;
}

std::vector<LaneRun> spread_in_lanes(std::span<const Chain> chains, std::span<const State> initials,
                                     const IntegrationConfig& config, std::span<const std::vector<Observer*>> observers) {
  validate(config);
  if (!runs_in_lanes(config))
    throw InvalidInput("integrator", ": the reference integrator, damping and the tangent map run one chain at a time");
  const std::size_t lanes = chains.size();
  if (initials.size() != lanes || observers.size() != lanes)
    throw InvalidInput("lanes: " + std::to_string(lanes) + " chains, " + std::to_string(initials.size()) +
                       " initial states, " + std::to_string(observers.size()) + " observer lists");
  for (std::size_t l = 0; l < lanes; ++l) validate_propagation(chains[l], config.time_step, initials[l]);
  const double tau = config.time_step;
  const RunPlan plan{chains.empty() ? 0 : chains.front().size(),
                     static_cast<std::uint64_t>(std::llround(config.duration / tau)), tau, config.duration};

  // spread()'s stops, per lane, merged: (step, lane, observer); observers[lane].size(): none.
  std::vector<std::tuple<std::uint64_t, std::size_t, std::size_t>> events;
  for (std::size_t l = 0; l < lanes; ++l)
    for (const auto& [step, who] : detail::observation_events(observers[l], plan)) events.emplace_back(step, l, who);
  std::sort(events.begin(), events.end());

  std::vector<ForceLaw> laws;
  std::vector<LaneRun> runs(lanes);
  for (std::size_t l = 0; l < lanes; ++l) {
    laws.push_back(make_force_law(config.force_law, chains[l]));
    runs[l].info.initial_energy = total_energy(laws[l], chains[l], initials[l]);
    if (!(runs[l].info.initial_energy > 0)) throw InvalidInput("initial state: carries no energy");
  }
  LanePropagator p(laws, chains, config.integrator.scheme, tau, initials, config.window);

  std::vector<std::unique_ptr<Snapshot>> now;
  std::vector<std::vector<double>> u(lanes), v(lanes);
  std::vector<bool> current(lanes, false);
  for (std::size_t l = 0; l < lanes; ++l)
    now.push_back(std::make_unique<Snapshot>(chains[l], laws[l], runs[l].info.initial_energy));
  double seconds = 0;
  const auto bring_up = [&](std::size_t l) {  // lane l's snapshot at the propagator's step
    if (current[l]) return;
    if (u[l].empty()) p.copy_lane(l, u[l], v[l]);
    else p.refresh_lane(l, u[l], v[l]);
    Snapshot& s = *now[l];
    s.step = p.steps_done();
    s.t = static_cast<double>(s.step) * tau;
    s.u = u[l];
    s.v = v[l];
    s.window_begin = p.window_begin(l);
    s.window_end = p.window_end(l);
    s.dissipated = 0;
    s.moved();
    current[l] = true;
  };
  bool first = true;
  for (const auto& [step, lane, who] : events) {
    if (first || step != p.steps_done()) {
      const auto t0 = std::chrono::steady_clock::now();
      p.advance(step - p.steps_done());
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::fill(current.begin(), current.end(), false);
      first = false;
    }
    if (who >= observers[lane].size() || runs[lane].failure) continue;
    bring_up(lane);
    try {
      observers[lane][who]->observe(*now[lane]);
    } catch (...) {
      runs[lane].failure = std::current_exception();  // this chain stops here; the others go on
    }
  }
  for (std::size_t l = 0; l < lanes; ++l) {
    LaneRun& run = runs[l];
    if (!run.failure) {
      bring_up(l);
      try {
        for (Observer* o : observers[l]) o->finish(*now[l]);
      } catch (...) {
        run.failure = std::current_exception();
      }
    }
    run.info.steps = p.steps_done();
    run.info.bond_updates = p.bond_updates(l);
    run.info.window_begin = p.window_begin(l);
    run.info.window_end = p.window_end(l);
    run.info.seconds = seconds;
  }
  return runs;
}

}  // namespace granular
