#pragma once
// `butterfly --from dynamics` (study/dynamical_butterfly.hpp): the run's flags — duration, step,
// integrator, force law, the initial velocities' amplitude and seed, the spectrum's samples — and
// the rule that a flag of one mode (these, or the eigen mode's box-counting flags) is refused in
// the other rather than silently ignored.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/integrator.hpp"
#include "granular/error.hpp"
#include "granular/study/dynamical_butterfly.hpp"
#include "tool_main.hpp"

namespace granular::tool {

struct DynamicalButterflyOptions {
  std::string from = "eigen";
  double duration = 1e-2, time_step = 1e-6, amplitude = 1e-5, max_energy_error = 1e-3;
  long long velocity_seed = 1, samples = 2001;
  std::string integrator = "saba2c", force_law = "hertz";
};

inline const std::vector<std::string>& dynamics_only_flags() {
  static const std::vector<std::string> flags{
      "--T",          "--dt",        "--amplitude",       "--velocity-seed", "--spectrum-samples",
      "--integrator", "--force-law", "--max-energy-error"};
  return flags;
}

inline void add_dynamical_butterfly_options(CLI::App& app, DynamicalButterflyOptions& o) {
  add_option(app, "--from", o.from,
             "eigen: every mode by the linear solver; dynamics: the power spectrum of a run from small random "
             "velocities of every bead (CSV columns ratio,freq_khz,power)");
  add_option(app, "--T", o.duration, "--from dynamics: duration [s]; the frequency resolution is 1/T");
  add_option(app, "--dt", o.time_step, "--from dynamics: time step tau [s]");
  add_option(app, "--amplitude", o.amplitude,
             "--from dynamics: initial velocities uniform in [-a, a] [m/s], small enough to stay linear");
  add_integer(app, "--velocity-seed", o.velocity_seed, "--from dynamics: seed of the initial velocities");
  add_integer(app, "--spectrum-samples", o.samples,
              "--from dynamics: uniform samples of [0, T] transformed (Nyquist about samples/(2T))");
  add_option(app, "--integrator", o.integrator, "--from dynamics: saba2c | saba2 | aba864 | srkn14a | reference");
  add_option(app, "--force-law", o.force_law, "--from dynamics: hertz | fpu | linear");
  add_option(app, "--max-energy-error", o.max_energy_error,
             "--from dynamics: relative energy error that stops a run, 0 = off");
}

/// Throws InvalidInput naming --from, or a flag given to the mode that does not read it.
inline bool from_dynamics(const CLI::App& app, const DynamicalButterflyOptions& o,
                          const std::vector<std::string>& eigen_only_flags) {
  if (o.from != "eigen" && o.from != "dynamics") throw InvalidInput("--from", " '" + o.from + "': eigen or dynamics");
  const bool dynamics = o.from == "dynamics";
  for (const std::string& flag : dynamics ? eigen_only_flags : dynamics_only_flags())
    if (app.count(flag) > 0)
      throw InvalidInput(flag, ": only with --from " + std::string(dynamics ? "eigen" : "dynamics"));
  return dynamics;
}

/// The library's config from the options (the chain, ratios and realization are set by the caller).
inline void apply(const DynamicalButterflyOptions& o, DynamicalButterflyConfig& c) {
  if (o.samples < 0) throw InvalidInput("--spectrum-samples", " " + std::to_string(o.samples) + ": at least 2");
  if (o.velocity_seed < 0) throw InvalidInput("--velocity-seed", " " + std::to_string(o.velocity_seed) + ": >= 0");
  c.integration.duration = o.duration;
  c.integration.time_step = o.time_step;
  c.integration.integrator = parse_integrator(o.integrator);
  c.integration.force_law = parse_force_law(o.force_law);
  c.amplitude = o.amplitude;
  c.velocity_seed = static_cast<std::uint64_t>(o.velocity_seed);
  c.spectrum_samples = static_cast<std::size_t>(o.samples);
  c.max_energy_error = o.max_energy_error;
}

}  // namespace granular::tool
