#include "granular/dynamics/spreading.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>

#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/spectral_density.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {

Sampling parse_sampling(const std::string& name) {
  if (name == "log") return Sampling::logarithmic;
  if (name == "uniform") return Sampling::uniform;
  throw InvalidInput("sampling", " '" + name + "': expected log or uniform");
}

SpectrumSource parse_spectrum_source(const std::string& name) {
  if (name == "displacement") return SpectrumSource::displacement;
  if (name == "velocity") return SpectrumSource::velocity;
  throw InvalidInput("spectrum_source", " '" + name + "': expected displacement or velocity");
}

std::string to_string(SpectrumSource source) {
  return source == SpectrumSource::displacement ? "displacement" : "velocity";
}

namespace {

std::uint64_t total_steps(const SpreadingConfig& c) {
  return static_cast<std::uint64_t>(std::llround(c.duration / c.time_step));
}

}  // namespace

void validate(const SpreadingConfig& c, std::size_t beads) {
  if (!std::isfinite(c.time_step) || !(c.time_step > 0))
    throw InvalidInput("time_step", " " + format_number(c.time_step) + ": the time step must be finite and > 0");
  if (!std::isfinite(c.duration) || !(c.duration > 0))
    throw InvalidInput("duration", " " + format_number(c.duration) + ": the duration must be finite and > 0");
  const double ratio = c.duration / c.time_step;
  if (ratio > 1e12)
    throw InvalidInput("duration", " " + format_number(c.duration) + " s / time_step " + format_number(c.time_step) +
                                       " s: more than 1e12 steps");
  if (ratio < 1 || std::abs(ratio - std::round(ratio)) > 1e-6 * ratio)
    throw InvalidInput("duration", " " + format_number(c.duration) + ": must be a whole number (>= 1) of time steps " +
                                       format_number(c.time_step));
  if (c.samples < 2) throw InvalidInput("samples", ": at least 2");
  if (c.integrator != "reference") parse_scheme(c.integrator);
  validate(c.damping);
  if (c.damping.any() && c.integrator == "reference")
    throw InvalidInput("integrator", " reference: has no damping; use a splitting scheme");
  if (c.lyapunov.enabled && c.integrator == "reference")
    throw InvalidInput("integrator", " reference: has no tangent map; use a splitting scheme");
  if (c.lyapunov.enabled && c.damping.any())
    throw InvalidInput("lyapunov", ": the tangent map is of the conservative flow; switch the damping off");
  if (c.deviation_samples > 0 && !c.lyapunov.enabled)
    throw InvalidInput("deviation_samples", ": needs the Lyapunov exponent switched on");
  if (c.deviation_samples == 1) throw InvalidInput("deviation_samples", ": 0 (none) or at least 2");
  for (std::size_t s : c.force_sites)
    if (s >= beads)
      throw InvalidInput("forces_at", " " + std::to_string(s + 1) + ": outside the chain of " + std::to_string(beads) +
                                          " beads (counting from 1)");
  if (!c.force_sites.empty() && c.force_samples < 2) throw InvalidInput("force_samples", ": at least 2");
  if (c.map_samples == 1) throw InvalidInput("map_samples", ": 0 (none) or at least 2");
  if (c.map_stride < 1) throw InvalidInput("map_stride", ": at least 1");
  if (c.spectrum_samples == 1) throw InvalidInput("spectrum_samples", ": 0 (none) or at least 2");
  if (c.spectrum_samples * beads > (std::size_t{1} << 31)) throw InvalidInput("spectrum_samples", ": too many for N");
  if (!(c.window.threshold >= 0)) throw InvalidInput("window_threshold", ": must be >= 0");
  if (c.site != static_cast<std::size_t>(-1) && c.site >= beads)
    throw InvalidInput("site",
                       " " + std::to_string(c.site + 1) + ": outside the chain of " + std::to_string(beads) + " beads");
  if (!c.dense.empty()) {
    const DenseGrid& g = c.dense;
    if (!std::isfinite(g.begin) || !std::isfinite(g.end) || g.begin < 0 || g.end > c.duration * (1 + 1e-12))
      throw InvalidInput("fit", " [" + format_number(g.begin) + ", " + format_number(g.end) +
                                    "] s: must lie inside [0, T = " + format_number(c.duration) + "]");
    const double stride = g.step / c.time_step;
    if (!std::isfinite(stride) || stride < 1 - 1e-9 || std::abs(stride - std::round(stride)) > 1e-6 * stride)
      throw InvalidInput("fit_step", " " + format_number(g.step) + " s: must be a whole number (>= 1) of time steps " +
                                         format_number(c.time_step) + " s");
    if ((g.end - g.begin) / g.step > 1e8)
      throw InvalidInput("fit_step", " " + format_number(g.step) + " s: more than 1e8 samples");
  }
}

std::vector<std::uint64_t> sample_steps(std::uint64_t total, std::size_t count, Sampling sampling) {
  std::vector<std::uint64_t> steps;
  if (sampling == Sampling::logarithmic) {
    const double span = std::log(static_cast<double>(total));
    for (std::size_t j = 0; j < count; ++j) {
      const double x = count == 1 ? 1.0 : static_cast<double>(j) / static_cast<double>(count - 1);
      steps.push_back(std::clamp<std::uint64_t>(static_cast<std::uint64_t>(std::llround(std::exp(x * span))), 1, total));
    }
    steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  } else {
    const std::uint64_t stride = std::max<std::uint64_t>(1, total / (count - 1));
    for (std::size_t j = 0; j < count && j * stride <= total; ++j) steps.push_back(j * stride);
  }
  return steps;
}

std::vector<std::uint64_t> sample_steps(const SpreadingConfig& c) {
  const std::uint64_t total = total_steps(c);
  std::vector<std::uint64_t> steps = sample_steps(total, c.samples, c.sampling);
  if (c.dense.empty()) return steps;
  const auto at = [&](double t) { return static_cast<std::uint64_t>(std::llround(t / c.time_step)); };
  const std::uint64_t begin = at(c.dense.begin), end = std::min(at(c.dense.end), total);
  const std::uint64_t stride = std::max<std::uint64_t>(1, at(c.dense.step));
  std::erase_if(steps, [&](std::uint64_t s) { return s >= begin && s <= end; });
  for (std::uint64_t s = begin; s <= end; s += stride) steps.push_back(s);
  steps.push_back(end);
  std::sort(steps.begin(), steps.end());
  steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  return steps;
}

SpreadingResult run_spreading(const Chain& chain, const State& initial, const SpreadingConfig& config) {
  const std::size_t n = chain.size();
  validate(config, n);
  validate_propagation(chain, config.time_step, initial);
  const ForceLaw law = make_force_law(config.force_law, chain);
  const std::uint64_t total = total_steps(config);
  const double tau = config.time_step;

  SpreadingResult r;
  r.initial_energy = total_energy(law, chain, initial);
  if (!(r.initial_energy > 0)) throw InvalidInput("initial state: carries no energy");

  TangentPropagator* tangent = nullptr;
  std::unique_ptr<Propagator> p =
      config.integrator == "reference" ? make_reference_propagator(law, chain, tau, initial, config.reference)
      : config.lyapunov.enabled
          ? make_tangent_propagator(law, chain, parse_scheme(config.integrator), tau, initial,
                                    localized_deviation(n, config.site < n ? config.site : centre_site(n),
                                                        config.lyapunov.time_unit),
                                    config.lyapunov)
      : config.damping.any()
          ? make_damped_propagator(law, chain, parse_scheme(config.integrator), tau, initial, config.damping)
          : make_splitting_propagator(law, chain, parse_scheme(config.integrator), tau, initial, config.window);

  if (config.lyapunov.enabled) tangent = static_cast<TangentPropagator*>(p.get());

  // The schedule: step number → what to measure there.
  enum : unsigned { spread = 1, force = 2, map = 4, spectrum = 8, deviation = 16 };
  std::map<std::uint64_t, unsigned> events;
  for (auto s : sample_steps(config)) events[s] |= spread;
  if (!config.force_sites.empty())
    for (auto s : sample_steps(total, config.force_samples, Sampling::uniform)) events[s] |= force;
  if (config.map_samples > 0)
    for (auto s : sample_steps(total, config.map_samples, Sampling::uniform)) events[s] |= map;
  std::uint64_t spectrum_stride = 0;
  if (config.spectrum_samples > 0) {
    const auto steps = sample_steps(total, config.spectrum_samples, Sampling::uniform);
    spectrum_stride = steps.size() > 1 ? steps[1] : 1;
    for (auto s : steps) events[s] |= spectrum;
  }
  if (config.deviation_samples > 0)
    for (auto s : sample_steps(total, config.deviation_samples, Sampling::uniform)) events[s] |= deviation;
  events[total] |= 0;  // always end at T

  const std::size_t site = config.site < n ? config.site : centre_site(n);
  std::vector<double> energy(n), bead_force(n), spectrum_rows;
  r.forces.assign(config.force_sites.size(), {});
  r.map_columns = (n + config.map_stride - 1) / config.map_stride;
  double integration = 0;
  for (const auto& [step, what] : events) {
    const auto t0 = std::chrono::steady_clock::now();
    p->advance(step - p->steps_done());
    integration += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double t = static_cast<double>(step) * tau;
    const auto u = p->displacement();
    if (what & (spread | map)) {
      // Beads outside the active window (± 1 for the edge bonds) are exactly at rest.
      const std::size_t lo = p->window_begin(), hi = p->window_end();
      site_energies(law, chain, u, p->velocity(), energy, lo, hi);
      if (what & spread) {
        const EnergySpread s = energy_spread(energy, site);
        const double h = s.total + unowned_wall_energy(law, u) + p->dissipated_energy();
        const double error = std::abs(h - r.initial_energy) / r.initial_energy;
        r.t.push_back(t);
        r.m2.push_back(s.m2_site);
        r.m2_centroid.push_back(s.m2_centroid);
        r.ipr.push_back(s.ipr);
        r.energy_error.push_back(error);
        if (config.damping.any()) r.dissipated.push_back(p->dissipated_energy());
        if (tangent) r.mle.push_back(tangent->mle());
        r.max_energy_error = std::max(r.max_energy_error, error);
        r.wall_energy = std::max(r.wall_energy, (energy[0] + energy[n - 1]) / r.initial_energy);
        if (!std::isfinite(h) || !std::isfinite(s.m2_site))
          throw NumericalError("the state became non-finite (NaN or inf) at t = " + format_number(t) + " s");
        if (config.max_energy_error > 0 && error > config.max_energy_error) {
          if (config.stop_on_energy_error)
            throw NumericalError("relative energy error " + format_number(error) + " at t = " + format_number(t) +
                                 " s exceeds --max-energy-error " + format_number(config.max_energy_error) +
                                 " (a smaller --dt helps)");
          if (r.energy_guard_time < 0) r.energy_guard_time = t;
        }
      }
      if (what & map) {
        r.map_t.push_back(t);
        for (std::size_t c = 0; c < r.map_columns; ++c) {
          double sum = 0;
          for (std::size_t i = c * config.map_stride; i < std::min(n, (c + 1) * config.map_stride); ++i)
            sum += energy[i];
          r.map_energy.push_back(sum);
        }
      }
    }
    if ((what & deviation) && tangent) {
      r.deviation_t.push_back(t);
      const std::vector<double> share = tangent->deviation_distribution();
      r.deviation.insert(r.deviation.end(), share.begin(), share.end());
    }
    if (what & force) {
      particle_forces(law, u, bead_force);
      r.force_t.push_back(t);
      for (std::size_t j = 0; j < config.force_sites.size(); ++j)
        r.forces[j].push_back(bead_force[config.force_sites[j]]);
    }
    if (what & spectrum) {
      const auto series = config.spectrum_source == SpectrumSource::displacement ? u : p->velocity();
      spectrum_rows.insert(spectrum_rows.end(), series.begin(), series.end());
    }
  }
  r.seconds = integration;
  r.final_state = p->state();
  r.final_energy = site_energies(law, chain, r.final_state);
  r.final_force = particle_forces(law, r.final_state);
  r.reached_walls = r.wall_energy > config.wall_warning;
  r.steps = p->steps_done();
  r.bond_updates = p->bond_updates();
  r.window_begin = p->window_begin();
  r.window_end = p->window_end();
  if (!spectrum_rows.empty()) {
    const std::size_t k = spectrum_rows.size() / n;
    SpectralDensity density(n, k);
    density.compute(spectrum_rows, r.spectrum);
    const double dt = static_cast<double>(spectrum_stride) * tau;
    for (std::size_t j = 0; j < density.frequencies(); ++j) r.spectrum_khz.push_back(density.frequency_khz(j, dt));
  }
  return r;
}

}  // namespace granular
