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
  std::string from = "eigen";
  DynamicalButterflyConfig config;            ///< the caller sets the chain, ratios and realization
  std::vector<std::string> dynamics_flags{};  ///< the flags only --from dynamics reads
};

inline void add_dynamical_butterfly_options(CLI::App& app, DynamicalButterflyOptions& o) {
  DynamicalButterflyConfig& c = o.config;
  add_option(app, "--from", o.from,
             "eigen: every mode by the linear solver; dynamics: the power spectrum of a run from small random "
             "velocities of every bead (CSV columns ratio,freq_khz,power)");
  const auto dynamics_only = [&o](CLI::Option* option) {  // its help says the mode that reads it
    option->description("--from dynamics: " + option->get_description());
    o.dynamics_flags.push_back(option->get_name());
  };
  for (const auto& [name, option] : add_parameters(app, c, dynamical_butterfly_parameters())) dynamics_only(option);
}

/// Whether --from asks for dynamics. Throws
/// InvalidInput naming --from, or a flag given to the mode that does not read it.
inline bool from_dynamics(const CLI::App& app, DynamicalButterflyOptions& o,
                          const std::vector<std::string>& eigen_only_flags) {
  if (o.from != "eigen" && o.from != "dynamics") throw InvalidInput("--from", " '" + o.from + "': eigen or dynamics");
  const bool dynamics = o.from == "dynamics";
  for (const std::string& flag : dynamics ? eigen_only_flags : o.dynamics_flags)
    if (app.count(flag) > 0)
      throw InvalidInput(flag, ": only with --from " + std::string(dynamics ? "eigen" : "dynamics"));
  return dynamics;
}

}  // namespace granular::tool
