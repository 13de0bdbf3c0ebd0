#include "granular/dynamics/spreading.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>

#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/spectral_density.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {

Sampling parse_sampling(const std::string& name) {
  if (name == "log") return Sampling::logarithmic;
  if (name == "uniform") return Sampling::uniform;
  throw InvalidInput("--sampling '" + name + "': expected log or uniform");
}

namespace {

std::uint64_t total_steps(const SpreadingConfig& c) {
  return static_cast<std::uint64_t>(std::llround(c.duration / c.time_step));
}

}  // namespace

void validate(const SpreadingConfig& c, std::size_t beads) {
  if (!std::isfinite(c.time_step) || !(c.time_step > 0))
    throw InvalidInput("--dt " + format_number(c.time_step) + ": the time step must be finite and > 0");
  if (!std::isfinite(c.duration) || !(c.duration > 0))
    throw InvalidInput("--T " + format_number(c.duration) + ": the duration must be finite and > 0");
  const double ratio = c.duration / c.time_step;
  if (ratio > 1e12) throw InvalidInput("--T / --dt: more than 1e12 steps");
  if (ratio < 1 || std::abs(ratio - std::round(ratio)) > 1e-6 * ratio)
    throw InvalidInput("--T " + format_number(c.duration) + ": must be a whole number (>= 1) of steps --dt " +
                       format_number(c.time_step));
  if (c.samples < 2) throw InvalidInput("--samples: at least 2");
  if (c.integrator != "reference") parse_scheme(c.integrator);
  for (std::size_t s : c.force_sites)
    if (s >= beads)
      throw InvalidInput("--forces-at " + std::to_string(s + 1) + ": outside the chain of " + std::to_string(beads) +
                         " beads (counting from 1)");
  if (!c.force_sites.empty() && c.force_samples < 2) throw InvalidInput("--force-samples: at least 2");
  if (c.map_samples == 1) throw InvalidInput("--map-samples: 0 (none) or at least 2");
  if (c.map_stride < 1) throw InvalidInput("--map-stride: at least 1");
  if (c.spectrum_samples == 1) throw InvalidInput("--spectrum-samples: 0 (none) or at least 2");
  if (c.spectrum_samples * beads > (std::size_t{1} << 31)) throw InvalidInput("--spectrum-samples: too many for N");
  if (!(c.window.threshold >= 0)) throw InvalidInput("--window-threshold: must be >= 0");
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

  std::unique_ptr<Propagator> p = config.integrator == "reference"
      ? make_reference_propagator(law, chain, tau, initial, config.reference)
      : make_splitting_propagator(law, chain, parse_scheme(config.integrator), tau, initial, config.window);

  // The schedule: step number → what to measure there.
  enum : unsigned { spread = 1, force = 2, map = 4, spectrum = 8 };
  std::map<std::uint64_t, unsigned> events;
  for (auto s : sample_steps(total, config.samples, config.sampling)) events[s] |= spread;
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
  events[total] |= 0;  // always end at T

  std::vector<double> energy(n), bead_force(n), u_rows;
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
        const EnergySpread s = energy_spread(energy);
        const double h = s.total + unowned_wall_energy(law, u);
        const double error = std::abs(h - r.initial_energy) / r.initial_energy;
        r.t.push_back(t);
        r.m2.push_back(s.m2);
        r.ipr.push_back(s.ipr);
        r.energy_error.push_back(error);
        r.max_energy_error = std::max(r.max_energy_error, error);
        r.wall_energy = std::max(r.wall_energy, (energy[0] + energy[n - 1]) / r.initial_energy);
        if (!std::isfinite(h) || !std::isfinite(s.m2))
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
          for (std::size_t i = c * config.map_stride; i < std::min(n, (c + 1) * config.map_stride); ++i) sum += energy[i];
          r.map_energy.push_back(sum);
        }
      }
    }
    if (what & force) {
      particle_forces(law, u, bead_force);
      r.force_t.push_back(t);
      for (std::size_t j = 0; j < config.force_sites.size(); ++j) r.forces[j].push_back(bead_force[config.force_sites[j]]);
    }
    if (what & spectrum) u_rows.insert(u_rows.end(), u.begin(), u.end());
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
  if (!u_rows.empty()) {
    const std::size_t k = u_rows.size() / n;
    SpectralDensity density(n, k);
    density.compute(u_rows, r.spectrum);
    const double dt = static_cast<double>(spectrum_stride) * tau;
    for (std::size_t j = 0; j < density.frequencies(); ++j) r.spectrum_khz.push_back(density.frequency_khz(j, dt));
  }
  return r;
}

}  // namespace granular
