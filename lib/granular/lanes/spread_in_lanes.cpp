// The driver of spread.cpp over a LanePropagator: the same schedule, the same snapshots, per lane.
#include "granular/lanes/spread_in_lanes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <tuple>
#include <utility>

#include <stdexcept>
#include <type_traits>
#include "granular/dynamics/detail/observation_events.hpp"

#include "granular/dynamics/observables.hpp"
#include "granular/error.hpp"
#include "granular/lanes/lane_propagator.hpp"
#include "granular/lanes/lane_tangent_propagator.hpp"

namespace granular {

namespace {

/// One lane of a LaneTangentPropagator as observers see a run's tangent map (Snapshot::tangent):
/// what TangentPropagator would answer at the snapshot's step, copied when the snapshot is made.
class LaneTangentView final : public TangentPropagator {
 public:
  void take(const LaneTangentPropagator& p, std::size_t lane, std::span<const double> u, std::span<const double> v) {
    p_ = &p, lane_ = lane, u_ = u, v_ = v;
    copied_ = false;  // the deviation vector is copied only if an observer asks for it
  }
  void advance(std::size_t) override { throw std::logic_error("a lane's tangent map is advanced by its lanes"); }
  std::span<const double> displacement() const override { return u_; }
  std::span<const double> velocity() const override { return v_; }
  double time_step() const override { return p_->time_step(); }
  std::uint64_t steps_done() const override { return p_->steps_done(); }
  std::uint64_t bond_updates() const override { return p_->bond_updates(lane_); }
  std::span<const double> deviation_displacement() const override { return copy().first; }
  std::span<const double> deviation_velocity() const override { return copy().second; }
  std::size_t deviation_count() const override { return 1; }
  std::span<const double> deviation_displacement(std::size_t) const override { return copy().first; }
  std::span<const double> deviation_velocity(std::size_t) const override { return copy().second; }
  void set_deviation(std::size_t, std::span<const double>, std::span<const double>) override {
    throw std::logic_error("a lane's tangent map carries one vector, set by its lanes");
  }
  double log_stretch() const override { return p_->log_stretch(lane_); }
  double time_unit() const override { return p_->time_unit(); }

 private:
  std::pair<std::span<const double>, std::span<const double>> copy() const {
    if (!copied_) p_->copy_deviation(lane_, du_, dv_), copied_ = true;
    return {du_, dv_};
  }
  const LaneTangentPropagator* p_ = nullptr;
  std::size_t lane_ = 0;
  std::span<const double> u_, v_;
  mutable std::vector<double> du_, dv_;
  mutable bool copied_ = false;
};

/// spread()'s loop over `p` (a LanePropagator, or a LaneTangentPropagator for the tangent map).
template <class Lanes>
std::vector<LaneRun> drive(Lanes& p, std::span<const Chain> chains, std::span<const ForceLaw> laws,
                           std::vector<LaneRun> runs, const RunPlan& plan,
                           std::span<const std::vector<Observer*>> observers) {
  constexpr bool tangent = std::is_same_v<Lanes, LaneTangentPropagator>;
  const std::size_t lanes = chains.size();
  const double tau = plan.time_step;
  // spread()'s stops, per lane, merged: (step, lane, observer); observers[lane].size(): none.
  std::vector<std::tuple<std::uint64_t, std::size_t, std::size_t>> events;
  for (std::size_t l = 0; l < lanes; ++l)
    for (const auto& [step, who] : detail::observation_events(observers[l], plan)) events.emplace_back(step, l, who);
  std::sort(events.begin(), events.end());

  std::vector<std::unique_ptr<Snapshot>> now;
  std::vector<LaneTangentView> views(tangent ? lanes : 0);
  std::vector<std::vector<double>> u(lanes), v(lanes);
  std::vector<bool> current(lanes, false);
  for (std::size_t l = 0; l < lanes; ++l)
    now.push_back(std::make_unique<Snapshot>(chains[l], laws[l], runs[l].info.initial_energy));
  double seconds = 0;
  const auto bring_up = [&](std::size_t l) {  // lane l's snapshot at the propagator's step
    if (current[l]) return;
    Snapshot& s = *now[l];
    if constexpr (tangent) {
      p.copy_lane(l, u[l], v[l]);
      views[l].take(p, l, u[l], v[l]);
      s.tangent = &views[l];
      s.window_begin = 0, s.window_end = p.beads();
    } else {
      if (u[l].empty()) p.copy_lane(l, u[l], v[l]);
      else p.refresh_lane(l, u[l], v[l]);
      s.window_begin = p.window_begin(l);
      s.window_end = p.window_end(l);
    }
    s.step = p.steps_done();
    s.t = static_cast<double>(s.step) * tau;
    s.u = u[l];
    s.v = v[l];
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
      if constexpr (tangent)  // where the lane's own TangentPropagator throws, its run stops
        for (std::size_t l = 0; l < lanes; ++l)
          if (!runs[l].failure && !p.failure(l).empty())
            runs[l].failure = std::make_exception_ptr(NumericalError(p.failure(l)));
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
    if constexpr (tangent) run.info.window_begin = 0, run.info.window_end = p.beads();
    else run.info.window_begin = p.window_begin(l), run.info.window_end = p.window_end(l);
    run.info.seconds = seconds;
  }
  return runs;
}

}  // namespace

bool runs_in_lanes(const IntegrationConfig& config) { return !config.integrator.reference && !config.damping.any(); }

std::vector<LaneRun> spread_in_lanes(std::span<const Chain> chains, std::span<const State> initials,
                                     const IntegrationConfig& config, std::span<const std::vector<Observer*>> observers) {
  validate(config);
  if (!runs_in_lanes(config))
    throw InvalidInput("integrator", ": the reference integrator and damping run one chain at a time");
  const std::size_t lanes = chains.size();
  if (initials.size() != lanes || observers.size() != lanes)
    throw InvalidInput("lanes: " + std::to_string(lanes) + " chains, " + std::to_string(initials.size()) +
                       " initial states, " + std::to_string(observers.size()) + " observer lists");
  for (std::size_t l = 0; l < lanes; ++l) validate_propagation(chains[l], config.time_step, initials[l]);
  const double tau = config.time_step;
  const RunPlan plan{chains.empty() ? 0 : chains.front().size(),
                     static_cast<std::uint64_t>(std::llround(config.duration / tau)), tau, config.duration};
  std::vector<ForceLaw> laws;
  std::vector<LaneRun> runs(lanes);
  for (std::size_t l = 0; l < lanes; ++l) {
    laws.push_back(make_force_law(config.force_law, chains[l]));
    runs[l].info.initial_energy = total_energy(laws[l], chains[l], initials[l]);
    if (!(runs[l].info.initial_energy > 0)) throw InvalidInput("initial state: carries no energy");
  }
  if (config.lyapunov.enabled) {
    std::vector<State> deviations;
    for (const Chain& chain : chains) deviations.push_back(starting_deviation(config, chain.size()));
    LaneTangentPropagator p(laws, chains, config.integrator.scheme, tau, initials, deviations, config.lyapunov);
    return drive(p, chains, laws, std::move(runs), plan, observers);
  }
  LanePropagator p(laws, chains, config.integrator.scheme, tau, initials, config.window);
  return drive(p, chains, laws, std::move(runs), plan, observers);
}

}  // namespace granular
