#include "granular/study/spreading_run.hpp"

#include <cmath>
#include <optional>
#include <string>

#include "granular/dynamics/sampling.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

RunPlan plan_of(const SpreadingRunConfig& run, std::size_t beads) {
  const IntegrationConfig& i = run.integration;
  return {beads, static_cast<std::uint64_t>(std::llround(i.duration / i.time_step)), i.time_step, i.duration};
}

}  // namespace

IntegrationConfig integration_config(const SpreadingRunConfig& run) {
  IntegrationConfig config = run.integration;
  config.deviation_site = run.spread.site;
  return config;
}

LyapunovObserver::Settings lyapunov_settings(const SpreadingRunConfig& run) {
  return {run.spread, run.deviation_samples};
}

LyapunovSpectrumConfig lyapunov_spectrum_config(const SpreadingRunConfig& run) {
  return {.vectors = run.lyapunov_vectors,
          .orthonormalize_every = run.integration.lyapunov.renormalize_every,
          .time_unit = run.integration.lyapunov.time_unit};
}

void validate(const SpreadingRunConfig& run, std::size_t beads) {
  validate(integration_config(run));
  const RunPlan plan = plan_of(run, beads);
  run.spread.validate(plan);
  run.forces.validate(plan);
  if (run.energy_map) run.energy_map->validate(plan);
  if (run.spectrum) run.spectrum->validate(plan);
  if (run.deviation_samples > 0 && !run.integration.lyapunov.enabled)
    throw InvalidInput("deviation_samples", ": needs the Lyapunov exponent switched on");
  if (run.integration.lyapunov.enabled) lyapunov_settings(run).validate(plan);
  if (run.lyapunov_vectors > 0 && !run.integration.lyapunov.enabled)
    throw InvalidInput("lyapunov_vectors", ": needs the Lyapunov exponent switched on");
  if (run.lyapunov_vectors > 2 * beads)
    throw InvalidInput("lyapunov_vectors", " " + std::to_string(run.lyapunov_vectors) +
                                               ": between 1 and 2N = " + std::to_string(2 * beads) + " (0 = none)");
  if (run.lyapunov_vectors > 0 && run.integration.lyapunov.renormalize_every < 1)
    throw InvalidInput("renormalize", " 0: the spectrum's vectors are re-orthonormalized every >= 1 steps");
}

std::vector<std::uint64_t> sample_steps(const SpreadingRunConfig& run) {
  const std::uint64_t total = plan_of(run, 0).total_steps;
  const EnergySpreadObserver::Settings& s = run.spread;
  return with_dense_grid(sample_steps(total, s.samples, s.sampling), s.dense, total, run.integration.time_step);
}

SpreadingResult run_spreading(const Chain& chain, const State& initial, const SpreadingRunConfig& run) {
  validate(run, chain.size());
  EnergySpreadObserver spread_observer(run.spread);
  FinalStateObserver final_state;
  ForceObserver forces(run.forces);
  std::optional<EnergyMapObserver> map;
  std::optional<SpectralDensityObserver> spectrum;
  std::optional<LyapunovObserver> lyapunov;
  std::vector<Observer*> observers{&spread_observer, &forces, &final_state};
  if (run.energy_map) observers.push_back(&map.emplace(*run.energy_map));
  if (run.spectrum) observers.push_back(&spectrum.emplace(*run.spectrum));
  if (run.integration.lyapunov.enabled) observers.push_back(&lyapunov.emplace(lyapunov_settings(run)));
  const RunInfo info = spread(chain, initial, integration_config(run), observers);

  SpreadingResult r;
  r.t = std::move(spread_observer.t);
  r.m2 = std::move(spread_observer.m2);
  r.m2_centroid = std::move(spread_observer.m2_centroid);
  r.ipr = std::move(spread_observer.ipr);
  r.energy_error = std::move(spread_observer.energy_error);
  if (run.integration.damping.any()) r.dissipated = std::move(spread_observer.dissipated);
  if (lyapunov) {
    r.mle = std::move(lyapunov->mle);
    r.deviation_t = std::move(lyapunov->deviation_t);
    r.deviation = std::move(lyapunov->deviation);
  }
  if (run.lyapunov_vectors > 0)  // the orbit once more, with the vectors (the rules: the tangent map's, validated)
    r.lyapunov =
        lyapunov_series(make_force_law(run.integration.force_law, chain), chain, run.integration.integrator.scheme,
                        run.integration.time_step, initial, lyapunov_spectrum_config(run), sample_steps(run));
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
