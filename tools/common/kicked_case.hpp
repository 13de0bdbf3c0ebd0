#pragma once
// The kicked-chain case as `spreading` reads it: from its flags — the chain (chain_options.hpp,
// --N auto), the kick (--ic, the mode options), the dynamics and the tangent map — or whole from a
// case file (--case: a case description, as a replay file or a run's JSON holds it).
#include <set>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "chain_options.hpp"
#include "dynamics_options.hpp"
#include "granular/study/case_file.hpp"
#include "long_time_options.hpp"
#include "tool_main.hpp"

namespace granular::tool {

struct KickedCaseOptions {
  KickedCaseOptions() { chain.n = 2501; }
  ChainOptions chain;
  DynamicsOptions dynamics;
  ModeKick mode;
  std::string ic = "displacement";
  long long realizations = 1;
  std::string case_file;  ///< --case: the chain, kick and dynamics from a file instead of the flags
};

inline void add_kicked_case_options(CLI::App& app, KickedCaseOptions& o) {
  const std::size_t before = app.get_options().size();
  add_chain_options(app, o.chain);
  add_auto_length(app, o.chain.auto_n);
  add_option(app, "--ic", o.ic, "initial condition: displacement | velocity | mode (a linear mode: --mode, --mode-khz)");
  add_dynamics_options(app, o.dynamics);
  add_mode_kick_options(app, o.mode);
  add_lyapunov_options(app, o.dynamics);
  add_option(app, "--realizations", o.realizations, "realizations to average (ensemble means and exponents)");
  auto* file = app.add_option("--case", o.case_file,
                              "JSON of a case: a replay file a failed ensemble wrote, or a spreading run's PREFIX.json "
                              "(its parameters); sets the chain, the kick and the dynamics, so none of their flags "
                              "goes with it; --realization and --realizations still choose what runs");
  const std::set<std::string> still{"--realization", "--realizations", "--deviation", "--deviation-samples"};
  const auto options = app.get_options();
  for (std::size_t i = before; i + 1 < options.size(); ++i)
    if (!still.contains(options[i]->get_name())) options[i]->excludes(file);
}

struct KickedCase {
  TransportCase c;
  SelectedChain selected;  ///< the chain of --realization (the one a single run integrates)
};

/// The case the options give, before validation (outputs may still add observers to it):
/// `ensemble` when it averages realizations (an ensemble draws random chains, not a file's).
inline KickedCase kicked_case(KickedCaseOptions& o, bool ensemble) {
  if (o.realizations < 1) throw InvalidInput("--realizations " + std::to_string(o.realizations) + ": must be >= 1");
  KickedCase k;  // (not an aggregate initializer: GCC 12 destroys its members twice when one throws)
  TransportCase& c = k.c;
  if (!o.case_file.empty()) {
    c = read_case_file(o.case_file);
    BeyondOptions beyond;  // the tangent map as the file says, the deviation file as the flags say
    static_cast<BeyondChoices&>(beyond) = beyond_choices_of(c.dynamics);
    beyond.deviation = o.dynamics.deviation, beyond.deviation_samples = o.dynamics.deviation_samples;
    granular::apply(beyond_choices(beyond), c.dynamics);
    k.selected = granular::select_chain(c.chain, chain_realization(o.chain), {"R1_m", "beads", "radii_file"});
    warn(k.selected.warnings);
  } else {
    if (o.chain.auto_n) require_centre_kick(o.dynamics.site);
    c.chain = chain_recipe(o.chain);  // with --N auto, N 3 until sized below
    c.kick = parse_kick(o.ic);
    apply(o.mode, {c.kick}, c);
    apply(o.dynamics, c);
    fit_within_duration(c);  // a window beyond T: no exponents, a note
    nlohmann::json rule;
    if (o.chain.auto_n) {
      validate(c.chain);                       // a drawn two-type chain
      rule = to_json(size_for_long_times(c));  // N, the centre kick, the centred draw
    }
    k.selected = granular::select_chain(c.chain, chain_realization(o.chain), radius_options(o.chain));
    warn(k.selected.warnings);
    if (o.chain.auto_n) k.selected.description["N_rule"] = rule;
  }
  if (ensemble && (c.chain.given_types || c.chain.given_radii))
    throw InvalidInput("--realizations/--resume: an ensemble draws random chains; --config/--radii give one chain");
  c.realizations = static_cast<std::size_t>(o.realizations);
  c.profile_realizations = 0;  // E_n(T) only when an output asks for it
  return k;
}

/// Whether the case's time step is given (--dt, or a case file's): else the rule picks it.
inline bool step_given(const CLI::App& app) { return app.count("--dt") > 0 || app.count("--case") > 0; }

}  // namespace granular::tool
