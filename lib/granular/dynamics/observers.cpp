#include "granular/dynamics/observers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <new>
#include <string>

#include "granular/detail/enum_names.hpp"
#include "granular/detail/memory_limit.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/spectral_density.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {

std::span<const double> Snapshot::energy() const {
  if (!energy_ready_) {
    energy_.resize(u.size());
    site_energies(law_, chain_, u, v, energy_, window_begin, window_end);
    energy_ready_ = true;
  }
  return energy_;
}

State Snapshot::state() const {
  State s;
  s.u.assign(u.begin(), u.end());
  s.v.assign(v.begin(), v.end());
  return s;
}

namespace {

std::string outside(std::size_t site, std::size_t beads) {
  return " " + std::to_string(site + 1) + ": outside the chain of " + std::to_string(beads) + " beads";
}

}  // namespace

void EnergySpreadObserver::Settings::validate(const RunPlan& plan) const {
  if (samples < 2) throw InvalidInput("samples", ": at least 2");
  if (site != std::numeric_limits<std::size_t>::max() && site >= plan.beads)
    throw InvalidInput("site", outside(site, plan.beads));
  if (dense.empty()) return;
  const DenseGrid& g = dense;
  if (!std::isfinite(g.begin) || !std::isfinite(g.end) || g.begin < 0 || g.end > plan.duration * (1 + 1e-12))
    throw InvalidInput("fit", " [" + format_number(g.begin) + ", " + format_number(g.end) +
                                  "] s: must lie inside [0, T = " + format_number(plan.duration) + "]");
  const double stride = g.step / plan.time_step;
  if (!std::isfinite(stride) || stride < 1 - 1e-9 || std::abs(stride - std::round(stride)) > 1e-6 * stride)
    throw InvalidInput("fit_step", " " + format_number(g.step) + " s: must be a whole number (>= 1) of time steps " +
                                       format_number(plan.time_step) + " s");
  if ((g.end - g.begin) / g.step > 1e8)
    throw InvalidInput("fit_step", " " + format_number(g.step) + " s: more than 1e8 samples");
}

std::vector<std::uint64_t> EnergySpreadObserver::schedule(const RunPlan& plan) {
  settings_.validate(plan);
  for (auto* series : {&t, &m2, &m2_centroid, &ipr, &energy_error, &dissipated}) series->clear();
  max_energy_error = wall_energy = 0;
  energy_guard_time = -1;
  site_ = settings_.site < plan.beads ? settings_.site : centre_site(plan.beads);
  return with_dense_grid(sample_steps(plan.total_steps, settings_.samples, settings_.sampling), settings_.dense,
                         plan.total_steps, plan.time_step);
}

void EnergySpreadObserver::observe(const Snapshot& now) {
  const auto energy = now.energy();
  const std::size_t n = energy.size();
  // Only the window's beads and the one just outside each edge (half an edge bond) hold energy.
  const EnergySpread s =
      energy_spread(energy, site_, now.window_begin > 0 ? now.window_begin - 1 : 0, now.window_end + 1);
  const double h0 = now.initial_energy();
  const double h = s.total + unowned_wall_energy(now.law(), now.u) + now.dissipated;
  const double error = std::abs(h - h0) / h0;
  t.push_back(now.t);
  m2.push_back(s.m2_site);
  m2_centroid.push_back(s.m2_centroid);
  ipr.push_back(s.ipr);
  energy_error.push_back(error);
  dissipated.push_back(now.dissipated);
  max_energy_error = std::max(max_energy_error, error);
  wall_energy = std::max(wall_energy, (energy[0] + energy[n - 1]) / h0);
  if (!std::isfinite(h) || !std::isfinite(s.m2_site))
    throw NumericalError("the state became non-finite (NaN or inf) at t = " + format_number(now.t) + " s");
  if (settings_.max_energy_error > 0 && error > settings_.max_energy_error) {
    if (settings_.stop_on_energy_error)
      throw NumericalError("relative energy error " + format_number(error) + " at t = " + format_number(now.t) +
                           " s exceeds max_energy_error " + format_number(settings_.max_energy_error) +
                           " (a smaller time_step helps)");
    if (energy_guard_time < 0) energy_guard_time = now.t;
  }
}

void LyapunovObserver::Settings::validate(const RunPlan& plan) const {
  times.validate(plan);
  if (deviation_samples == 1) throw InvalidInput("deviation_samples", ": 0 (none) or at least 2");
}

std::vector<std::uint64_t> LyapunovObserver::schedule(const RunPlan& plan) {
  settings_.validate(plan);
  for (auto* series : {&t, &mle, &deviation_t, &deviation}) series->clear();
  x1_steps_ = with_dense_grid(sample_steps(plan.total_steps, settings_.times.samples, settings_.times.sampling),
                              settings_.times.dense, plan.total_steps, plan.time_step);
  deviation_steps_.clear();
  if (settings_.deviation_samples > 0)
    deviation_steps_ = sample_steps(plan.total_steps, settings_.deviation_samples, Sampling::uniform);
  next_x1_ = next_deviation_ = 0;
  std::vector<std::uint64_t> all = x1_steps_;
  all.insert(all.end(), deviation_steps_.begin(), deviation_steps_.end());
  return all;
}

void LyapunovObserver::observe(const Snapshot& now) {
  if (now.tangent == nullptr)
    throw InvalidInput("lyapunov", ": the run carries no tangent map (set IntegrationConfig::lyapunov.enabled)");
  if (next_x1_ < x1_steps_.size() && x1_steps_[next_x1_] == now.step) {
    t.push_back(now.t);
    mle.push_back(now.tangent->mle());
    ++next_x1_;
  }
  if (next_deviation_ < deviation_steps_.size() && deviation_steps_[next_deviation_] == now.step) {
    deviation_t.push_back(now.t);
    const std::vector<double> share = now.tangent->deviation_distribution();
    deviation.insert(deviation.end(), share.begin(), share.end());
    ++next_deviation_;
  }
}

void ForceObserver::Settings::validate(const RunPlan& plan) const {
  for (std::size_t s : sites)
    if (s >= plan.beads) throw InvalidInput("forces_at", outside(s, plan.beads) + " (counting from 1)");
  if (!sites.empty() && samples < 2) throw InvalidInput("force_samples", ": at least 2");
}

std::vector<std::uint64_t> ForceObserver::schedule(const RunPlan& plan) {
  settings_.validate(plan);
  t.clear();
  forces.assign(settings_.sites.size(), {});
  if (settings_.sites.empty()) return {};
  return sample_steps(plan.total_steps, settings_.samples, Sampling::uniform);
}

void ForceObserver::observe(const Snapshot& now) {
  buffer_.resize(now.u.size());
  particle_forces(now.law(), now.u, buffer_);
  t.push_back(now.t);
  for (std::size_t j = 0; j < settings_.sites.size(); ++j) forces[j].push_back(buffer_[settings_.sites[j]]);
}

void EnergyMapObserver::Settings::validate(const RunPlan& plan) const {
  if (samples < 2) throw InvalidInput("map_samples", ": at least 2");
  if (stride < 1) throw InvalidInput("map_stride", ": at least 1");
  // The whole map is kept until the run ends: refuse one that cannot fit now, not hours in with
  // bad_alloc. Half the memory this process may use (the least of RAM, its cgroup's limit and
  // ulimit -v) leaves room for the run itself and the output's copy.
  const double bytes = map_bytes(plan);
  const detail::MemoryLimit memory = detail::memory_limit();
  if (memory.bytes > 0 && bytes > memory.bytes / 2) {
    char text[300];
    std::snprintf(text, sizeof text,
                  " %zu: the energy map needs %.3g bytes (%.0f times x %.0f columns x 8), more than half of the "
                  "%.3g bytes this process may use (%s); take fewer samples, or sum more beads per column "
                  "(the stride)",
                  samples, bytes, map_times(plan), map_columns(plan), memory.bytes, memory.source.c_str());
    throw InvalidInput("map_samples", text);
  }
}

double EnergyMapObserver::Settings::map_times(const RunPlan& plan) const {
  return std::min(static_cast<double>(samples), static_cast<double>(plan.total_steps) + 1);
}

double EnergyMapObserver::Settings::map_columns(const RunPlan& plan) const {
  return std::ceil(static_cast<double>(plan.beads) / static_cast<double>(stride));
}

double EnergyMapObserver::Settings::map_bytes(const RunPlan& plan) const {
  return map_times(plan) * map_columns(plan) * sizeof(double);
}

std::vector<std::uint64_t> EnergyMapObserver::schedule(const RunPlan& plan) {
  settings_.validate(plan);
  t.clear();
  energy.clear();
  columns = (plan.beads + settings_.stride - 1) / settings_.stride;
  auto steps = sample_steps(plan.total_steps, settings_.samples, Sampling::uniform);
  // The whole map's memory now, before the run: a limit the guard above could not see (another
  // process's use, overcommit off) fails here, not at the last sample.
  try {
    t.reserve(steps.size());
    energy.reserve(steps.size() * columns);
  } catch (const std::bad_alloc&) {
    char text[200];
    std::snprintf(text, sizeof text, " %zu: the energy map's %.3g bytes could not be allocated", settings_.samples,
                  settings_.map_bytes(plan));
    throw InvalidInput("map_samples", text);
  }
  return steps;
}

void EnergyMapObserver::observe(const Snapshot& now) {
  const auto e = now.energy();
  const std::size_t n = e.size(), stride = settings_.stride;
  t.push_back(now.t);
  for (std::size_t c = 0; c < columns; ++c) {
    double sum = 0;
    for (std::size_t i = c * stride; i < std::min(n, (c + 1) * stride); ++i) sum += e[i];
    energy.push_back(sum);
  }
}

constexpr auto spectrum_source_names =
    detail::enum_names<SpectrumSource>("spectrum_source", {{SpectrumSource::displacement, "displacement"},
                                                           {SpectrumSource::velocity, "velocity"}});

SpectrumSource parse_spectrum_source(const std::string& name) { return spectrum_source_names.parse(name); }

std::string to_string(SpectrumSource source) { return std::string(spectrum_source_names.name_of(source)); }

void SpectralDensityObserver::Settings::validate(const RunPlan& plan) const {
  if (samples < 2) throw InvalidInput("spectrum_samples", ": at least 2");
  if (samples * plan.beads > (std::size_t{1} << 31)) throw InvalidInput("spectrum_samples", ": too many for N");
}

std::vector<std::uint64_t> SpectralDensityObserver::schedule(const RunPlan& plan) {
  settings_.validate(plan);
  freq_khz.clear();
  density.clear();
  rows_.clear();
  return sample_steps(plan.total_steps, settings_.samples, Sampling::uniform);
}

void SpectralDensityObserver::observe(const Snapshot& now) {
  if (rows_.size() == now.u.size()) sample_interval_ = now.t;  // the second sample: the first is at t = 0
  const auto series = settings_.source == SpectrumSource::displacement ? now.u : now.v;
  rows_.insert(rows_.end(), series.begin(), series.end());
}

void SpectralDensityObserver::finish(const Snapshot& at_T) {
  const std::size_t n = at_T.u.size();
  if (rows_.empty()) return;
  SpectralDensity g(n, rows_.size() / n);
  g.compute(rows_, density);
  for (std::size_t j = 0; j < g.frequencies(); ++j) freq_khz.push_back(g.frequency_khz(j, sample_interval_));
  rows_ = {};
}

void FinalStateObserver::finish(const Snapshot& at_T) {
  state = at_T.state();
  energy = site_energies(at_T.law(), at_T.chain(), state);
  force = particle_forces(at_T.law(), state);
}

}  // namespace granular
