#include "granular/dynamics/spreading.hpp"

#include <cmath>
#include <optional>

#include "granular/error.hpp"

namespace granular {
namespace {

RunPlan plan_of(const SpreadingConfig& c, std::size_t beads) {
  return {beads, static_cast<std::uint64_t>(std::llround(c.duration / c.time_step)), c.time_step, c.duration};
}

}  // namespace

IntegrationConfig integration_config(const SpreadingConfig& c) {
  return {.duration = c.duration,
          .time_step = c.time_step,
          .force_law = c.force_law,
          .integrator = c.integrator,
          .window = c.window,
          .damping = c.damping,
          .lyapunov = c.lyapunov,
          .deviation_site = c.site};
}

EnergySpreadObserver::Settings energy_spread_settings(const SpreadingConfig& c) {
  return {.samples = c.samples,
          .sampling = c.sampling,
          .dense = c.dense,
          .site = c.site,
          .max_energy_error = c.max_energy_error,
          .stop_on_energy_error = c.stop_on_energy_error,
          .wall_warning = c.wall_warning};
}

void validate(const SpreadingConfig& c, std::size_t beads) {
  validate(integration_config(c));
  const RunPlan plan = plan_of(c, beads);
  energy_spread_settings(c).validate(plan);
  ForceObserver::Settings{c.force_sites, c.force_samples}.validate(plan);
  if (c.map_samples > 0) EnergyMapObserver::Settings{c.map_samples, c.map_stride}.validate(plan);
  if (c.spectrum_samples > 0) SpectralDensityObserver::Settings{c.spectrum_samples, c.spectrum_source}.validate(plan);
  if (c.deviation_samples > 0 && !c.lyapunov.enabled)
    throw InvalidInput("deviation_samples", ": needs the Lyapunov exponent switched on");
  if (c.lyapunov.enabled) LyapunovObserver::Settings{energy_spread_settings(c), c.deviation_samples}.validate(plan);
}

std::vector<std::uint64_t> sample_steps(const SpreadingConfig& c) {
  const std::uint64_t total = plan_of(c, 0).total_steps;
  return with_dense_grid(sample_steps(total, c.samples, c.sampling), c.dense, total, c.time_step);
}

SpreadingResult run_spreading(const Chain& chain, const State& initial, const SpreadingConfig& config) {
  validate(config, chain.size());
  EnergySpreadObserver spread_observer(energy_spread_settings(config));
  FinalStateObserver final_state;
  ForceObserver forces({config.force_sites, config.force_samples});
  std::optional<EnergyMapObserver> map;
  std::optional<SpectralDensityObserver> spectrum;
  std::optional<LyapunovObserver> lyapunov;
  std::vector<Observer*> observers{&spread_observer, &forces, &final_state};
  if (config.map_samples > 0)
    observers.push_back(&map.emplace(EnergyMapObserver::Settings{config.map_samples, config.map_stride}));
  if (config.spectrum_samples > 0)
    observers.push_back(
        &spectrum.emplace(SpectralDensityObserver::Settings{config.spectrum_samples, config.spectrum_source}));
  if (config.lyapunov.enabled)
    observers.push_back(
        &lyapunov.emplace(LyapunovObserver::Settings{energy_spread_settings(config), config.deviation_samples}));
  const RunInfo info = spread(chain, initial, integration_config(config), observers);

  SpreadingResult r;
  r.t = std::move(spread_observer.t);
  r.m2 = std::move(spread_observer.m2);
  r.m2_centroid = std::move(spread_observer.m2_centroid);
  r.ipr = std::move(spread_observer.ipr);
  r.energy_error = std::move(spread_observer.energy_error);
  if (config.damping.any()) r.dissipated = std::move(spread_observer.dissipated);
  if (lyapunov) {
    r.mle = std::move(lyapunov->mle);
    r.deviation_t = std::move(lyapunov->deviation_t);
    r.deviation = std::move(lyapunov->deviation);
  }
  r.initial_energy = info.initial_energy;
  r.max_energy_error = spread_observer.max_energy_error;
  r.wall_energy = spread_observer.wall_energy;
  r.reached_walls = spread_observer.reached_walls();
  r.energy_guard_time = spread_observer.energy_guard_time;
  r.final_state = std::move(final_state.state);
  r.final_energy = std::move(final_state.energy);
  r.final_force = std::move(final_state.force);
  r.force_t = std::move(forces.t);
  r.forces = std::move(forces.forces);
  if (map) {
    r.map_t = std::move(map->t);
    r.map_energy = std::move(map->energy);
    r.map_columns = map->columns;
  } else {
    r.map_columns = (chain.size() + config.map_stride - 1) / config.map_stride;
  }
  if (spectrum) {
    r.spectrum_khz = std::move(spectrum->freq_khz);
    r.spectrum = std::move(spectrum->density);
  }
  r.steps = info.steps;
  r.bond_updates = info.bond_updates;
  r.window_begin = info.window_begin;
  r.window_end = info.window_end;
  r.seconds = info.seconds;
  return r;
}

}  // namespace granular
