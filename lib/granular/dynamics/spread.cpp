#include "granular/dynamics/spread.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "granular/dynamics/detail/observation_events.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {

void validate_step_and_duration(const IntegrationConfig& c) {
  if (!std::isfinite(c.time_step) || !(c.time_step > 0))
    throw InvalidInput("time_step", " " + format_number(c.time_step) + ": the time step must be finite and > 0");
  if (!std::isfinite(c.duration) || !(c.duration > 0))
    throw InvalidInput("duration", " " + format_number(c.duration) + ": the duration must be finite and > 0");
}

void validate(const IntegrationConfig& c) {
  validate_step_and_duration(c);
  const double ratio = c.duration / c.time_step;
  if (ratio > 1e12)
    throw InvalidInput("duration", " " + format_number(c.duration) + " s / time_step " + format_number(c.time_step) +
                                       " s: more than 1e12 steps");
  if (ratio < 1 || std::abs(ratio - std::round(ratio)) > 1e-6 * ratio)
    throw InvalidInput("duration", " " + format_number(c.duration) + ": must be a whole number (>= 1) of time steps " +
                                       format_number(c.time_step));
  if (!(c.window.threshold >= 0)) throw InvalidInput("window_threshold", ": must be >= 0");
  validate(c.damping);
  if (c.damping.any() && c.integrator.reference)
    throw InvalidInput("integrator", " reference: has no damping; use a splitting scheme");
  if (c.lyapunov.enabled && c.integrator.reference)
    throw InvalidInput("integrator", " reference: has no tangent map; use a splitting scheme");
  if (c.lyapunov.enabled && c.damping.any())
    throw InvalidInput("lyapunov", ": the tangent map is of the conservative flow; switch the damping off");
}

State starting_deviation(const IntegrationConfig& config, std::size_t beads) {
  const std::size_t site = config.deviation_site < beads ? config.deviation_site : centre_site(beads);
  return localized_deviation(beads, site, config.lyapunov.time_unit);
}

std::unique_ptr<Propagator> make_propagator(const IntegrationConfig& config, const ForceLaw& law, const Chain& chain,
                                            const State& initial) {
  if (config.lyapunov.enabled)
    return make_tangent_propagator(law, chain, config.integrator.scheme, config.time_step, initial,
                                   starting_deviation(config, chain.size()), config.lyapunov);
  if (config.damping.any())
    return make_damped_propagator(law, chain, config.integrator.scheme, config.time_step, initial, config.damping);
  return make_propagator(config.integrator, law, chain, config.time_step, initial, config.window);
}

namespace detail {

std::vector<std::pair<std::uint64_t, std::size_t>> observation_events(std::span<Observer* const> observers,
                                                                      const RunPlan& plan) {
  std::vector<std::pair<std::uint64_t, std::size_t>> events;  // (step, observer); observers.size(): none
  for (std::size_t i = 0; i < observers.size(); ++i)
    for (std::uint64_t s : observers[i]->schedule(plan))
      if (s <= plan.total_steps) events.emplace_back(s, i);
  events.emplace_back(plan.total_steps, observers.size());
  std::sort(events.begin(), events.end());
  events.erase(std::unique(events.begin(), events.end()), events.end());
  return events;
}

}  // namespace detail

RunInfo spread(const Chain& chain, const State& initial, const IntegrationConfig& config,
               std::span<Observer* const> observers) {
  validate(config);
  validate_propagation(chain, config.time_step, initial);
  const double tau = config.time_step;
  const RunPlan plan{chain.size(), static_cast<std::uint64_t>(std::llround(config.duration / tau)), tau,
                     config.duration};

  const auto events = detail::observation_events(observers, plan);

  const ForceLaw law = make_force_law(config.force_law, chain);
  RunInfo info;
  info.initial_energy = total_energy(law, chain, initial);
  if (!(info.initial_energy > 0)) throw InvalidInput("initial state: carries no energy");
  const std::unique_ptr<Propagator> p = make_propagator(config, law, chain, initial);

  Snapshot now(chain, law, info.initial_energy);
  now.tangent = dynamic_cast<const TangentPropagator*>(p.get());
  bool first = true;
  for (const auto& [step, who] : events) {
    if (first || step != now.step) {
      const auto t0 = std::chrono::steady_clock::now();
      p->advance(step - p->steps_done());
      info.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      now.step = step;
      now.t = static_cast<double>(step) * tau;
      now.u = p->displacement();
      now.v = p->velocity();
      now.window_begin = p->window_begin();
      now.window_end = p->window_end();
      now.dissipated = p->dissipated_energy();
      now.moved();
      first = false;
    }
    if (who < observers.size()) observers[who]->observe(now);
  }
  for (Observer* o : observers) o->finish(now);
  info.steps = p->steps_done();
  info.bond_updates = p->bond_updates();
  info.window_begin = p->window_begin();
  info.window_end = p->window_end();
  return info;
}

}  // namespace granular
