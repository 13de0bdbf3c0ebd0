#pragma once
// The kicked-chain case as `spreading` reads it from its flags: the chain (chain_options.hpp,
// --N auto), the kick (--ic, the mode options), the dynamics and the tangent map. One reading,
// used by the tool itself and by the replay command (replay_command.hpp), which checks that the
// command it prints reads back as the very case that failed.
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "chain_options.hpp"
#include "dynamics_options.hpp"
#include "long_time_options.hpp"
#include "mode_kick_options.hpp"
#include "tool_main.hpp"

namespace granular::tool {

struct KickedCaseOptions {
  KickedCaseOptions() { chain.n = 2501; }
  ChainOptions chain;
  DynamicsOptions dynamics;
  ModeKickOptions mode;
  std::string ic = "displacement";
  long long realizations = 1;
};

inline void add_kicked_case_options(CLI::App& app, KickedCaseOptions& o) {
  add_chain_options(app, o.chain);
  add_auto_length(app, o.chain.auto_n);
  add_option(app, "--ic", o.ic, "initial condition: displacement | velocity | mode (a linear mode: --mode, --mode-khz)");
  add_dynamics_options(app, o.dynamics);
  add_mode_kick_options(app, o.mode);
  add_lyapunov_options(app, o.dynamics);
  add_option(app, "--realizations", o.realizations, "realizations to average (ensemble means and exponents)");
}

struct KickedCase {
  TransportCase c;
  SelectedChain selected;  ///< the chain of --realization (the one a single run integrates)
};

/// The case the options give, before validation (outputs may still add observers to it):
/// `ensemble` when it averages realizations (an ensemble draws random chains, not a file's).
inline KickedCase kicked_case(KickedCaseOptions& o, bool ensemble) {
  if (o.realizations < 1) throw InvalidInput("--realizations " + std::to_string(o.realizations) + ": must be >= 1");
  if (ensemble && (!o.chain.config.empty() || !o.chain.radii.empty()))
    throw InvalidInput("--realizations/--resume: an ensemble draws random chains; --config/--radii give one chain");
  size_chain(o.chain, o.dynamics, o.ic);  // --N auto
  KickedCase k;  // (not an aggregate initializer: GCC 12 destroys its members twice when one throws)
  k.selected = build_chain(o.chain);
  TransportCase& c = k.c;
  c.chain = k.selected.recipe;
  c.kick = parse_kick(o.ic);
  apply(o.mode, c);
  c.realizations = static_cast<std::size_t>(o.realizations);
  c.profile_realizations = 0;  // E_n(T) only when an output asks for it
  apply(o.dynamics, c);
  c.fit = c.fit_end <= c.dynamics.integration.duration * (1 + 1e-12);  // a window beyond T: no exponents, a note
  return k;
}

}  // namespace granular::tool
