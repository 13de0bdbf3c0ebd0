#include "granular/case/spreading_run.hpp"

#include <cmath>
#include <cstdio>
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

CovariantVectorsConfig covariant_config(const SpreadingRunConfig& run) {
  const IntegrationConfig& i = run.integration;
  const auto transient =
      static_cast<std::size_t>(std::llround(run.covariant_transient.value_or(i.duration / 2) / i.time_step));
  return {.vectors = run.covariant_vectors,
          .orthonormalize_every = i.lyapunov.renormalize_every,
          .forward_transient = transient,
          .backward_transient = transient,
          .time_unit = i.lyapunov.time_unit};
}

std::vector<std::uint64_t> covariant_sample_steps(const SpreadingRunConfig& run) {
  const std::uint64_t forward = covariant_config(run).forward_transient;
  std::vector<std::uint64_t> steps;
  for (const std::uint64_t s : sample_steps(run))
    if (s >= forward) steps.push_back(s - forward);
  return steps;
}

namespace {
// Refused before the run, each naming the keyword: what covariant_vectors() would refuse only once it starts.
void validate_covariant(const SpreadingRunConfig& run, std::size_t beads) {
  const std::size_t k = run.covariant_vectors;
  if (k > 0 && !run.integration.lyapunov.enabled)
    throw InvalidInput("covariant_vectors", ": needs the Lyapunov exponent switched on");
  if (k > 2 * beads)
    throw InvalidInput("covariant_vectors",
                       " " + std::to_string(k) + ": between 1 and 2N = " + std::to_string(2 * beads) + " (0 = none)");
  const double transient = run.covariant_transient.value_or(0);
  if (!(transient >= 0) || !std::isfinite(transient))
    throw InvalidInput("covariant_transient", ": must be finite and >= 0 [s]");
  if (k == 0) return;
  if (run.integration.lyapunov.renormalize_every < 1)
    throw InvalidInput("renormalize", " 0: the covariant vectors' QR comes every >= 1 steps");
  const std::vector<std::uint64_t> steps = covariant_sample_steps(run);
  if (steps.empty()) throw InvalidInput("covariant_transient", ": leaves no sample time between it and T (none: T/2)");
  const CovariantMemory m = covariant_memory(covariant_config(run), beads, steps);
  if (!m.fits()) {
    char need[120];
    std::snprintf(need, sizeof need, ": the stored factors and vectors need %.3g bytes, more than the %.3g allowed (",
                  m.bytes, m.limit);
    throw InvalidInput("covariant_vectors", " " + std::to_string(k) + need + m.source +
                                                "); take fewer vectors, a shorter T or `covariant_transient`, or a "
                                                "longer `renormalize`");
  }
}
}  // namespace

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
  validate_covariant(run, beads);
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
  if (run.covariant_vectors > 0)  // that orbit again, on past T by the backward transient
    r.covariant =
        covariant_vectors(make_force_law(run.integration.force_law, chain), chain, run.integration.integrator.scheme,
                          run.integration.time_step, initial, covariant_config(run), covariant_sample_steps(run));
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
