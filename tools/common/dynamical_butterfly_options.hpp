#pragma once
// `butterfly --from dynamics` (study/dynamical_butterfly.hpp): the run's flags, bound straight into
// the library's config, and the rule that a flag of one mode (these, or the eigen mode's
// box-counting flags) is refused in the other rather than silently ignored.
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
  std::string from = "eigen", integrator = "saba2c", force_law = "hertz";
  DynamicalButterflyConfig config;  ///< the caller sets the chain, ratios and realization
};

inline void add_dynamical_butterfly_options(CLI::App& app, DynamicalButterflyOptions& o) {
  DynamicalButterflyConfig& c = o.config;
  add_option(app, "--from", o.from,
             "eigen: every mode by the linear solver; dynamics: the power spectrum of a run from small random "
             "velocities of every bead (CSV columns ratio,freq_khz,power)");
  add_option(app, "--T", c.integration.duration, "--from dynamics: duration [s]; the frequency resolution is 1/T");
  add_option(app, "--dt", c.integration.time_step, "--from dynamics: time step tau [s]");
  add_option(app, "--amplitude", c.amplitude,
             "--from dynamics: initial velocities uniform in [-a, a] [m/s], small enough to stay linear");
  add_integer(app, "--velocity-seed", c.velocity_seed, "--from dynamics: seed of the initial velocities");
  add_integer(app, "--spectrum-samples", c.spectrum_samples,
              "--from dynamics: uniform samples of [0, T] transformed (Nyquist about samples/(2T))");
  add_option(app, "--integrator", o.integrator, "--from dynamics: saba2c | saba2 | aba864 | srkn14a | reference");
  add_option(app, "--force-law", o.force_law, "--from dynamics: hertz | fpu | linear");
  add_option(app, "--max-energy-error", c.max_energy_error,
             "--from dynamics: relative energy error that stops a run, 0 = off");
}

/// Whether --from asks for dynamics, its scheme and force law read into the config. Throws
/// InvalidInput naming --from, or a flag given to the mode that does not read it.
inline bool from_dynamics(const CLI::App& app, DynamicalButterflyOptions& o,
                          const std::vector<std::string>& eigen_only_flags) {
  if (o.from != "eigen" && o.from != "dynamics") throw InvalidInput("--from", " '" + o.from + "': eigen or dynamics");
  const bool dynamics = o.from == "dynamics";
  const std::vector<std::string> dynamics_only_flags{
      "--T",          "--dt",        "--amplitude",       "--velocity-seed", "--spectrum-samples",
      "--integrator", "--force-law", "--max-energy-error"};
  for (const std::string& flag : dynamics ? eigen_only_flags : dynamics_only_flags)
    if (app.count(flag) > 0)
      throw InvalidInput(flag, ": only with --from " + std::string(dynamics ? "eigen" : "dynamics"));
  o.config.integration.integrator = parse_integrator(o.integrator);
  o.config.integration.force_law = parse_force_law(o.force_law);
  return dynamics;
}

}  // namespace granular::tool
