#pragma once
// The options that pick one chain (a ChainRecipe and its realization), shared by every
// single-chain tool: a random two-type draw, a types or radii file, k types, polydisperse radii or
// a quasiperiodic chain (one of them: the library refuses two); stored, or streamed for tools
// that walk it once (localization).
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "granular/case/chain_choices.hpp"
#include "granular/model/selected_chain.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// The chain's options bind straight into the library's choices (case/chain_choices.hpp).
using ChainOptions = ChainChoices;

/// --types, --type-masses, --polydisperse. `rule_flag`: the tool's flag that says how types are drawn.
inline void add_bead_distribution_options(CLI::App& app, ChainOptions& o, const std::string& rule_flag = "--disorder") {
  add_parameters(app, o, chain_parameters(),
                 {.only = {"types", "type_masses", "polydisperse"}, .flags = {{"disorder", rule_flag}}});
}

/// --quasi and its parameters (model/quasiperiodic.hpp).
inline void add_quasiperiodic_options(CLI::App& app, ChainOptions& o) {
  add_parameters(app, o, chain_parameters(),
                 {.only = {"quasi", "modulation", "ratio", "phase", "angle", "k0", "k0_n_per_m"}});
}

/// Every chain option: the two-type draw, the files, the bead distributions, the quasiperiodic chain
/// (`table`: chain_parameters, or long_run_chain_parameters where --N takes 'auto').
inline void add_chain_options(CLI::App& app, ChainOptions& o,
                              const ParameterTable<ChainChoices>& table = chain_parameters()) {
  add_parameters(app, o, table,
                 {.only = {"disorder", "xi", "q", "N", "F0", "R1", "walls", "seed", "realization", "config", "radii"}});
  add_quasiperiodic_options(app, o);
  add_bead_distribution_options(app, o);
}

/// The recipe the options pick (granular::chain_recipe), a radii file's warnings printed.
inline ChainRecipe chain_recipe(const ChainOptions& o) {
  std::vector<std::string> warnings;
  ChainRecipe r = granular::chain_recipe(o, warnings);
  warn(warnings);
  return r;
}

/// The options named in the warnings about implausible radii (granular::radius_names).
inline RadiusNames radius_options(const ChainOptions& o) {
  return radius_names(o, [](const std::string& p) { return option_name(front_end_word(p)); });
}

/// The chain the options pick, streamed (granular::stream_chain), its warnings printed; `defaults`:
/// the tool's own (what "given" is told against).
inline StreamedChain stream_chain(const ChainOptions& o, const ChainOptions& defaults) {
  StreamedChain s = granular::stream_chain(
      o, [](const std::string& p) { return option_name(front_end_word(p)); }, defaults);
  warn(s.warnings);
  return s;
}

}  // namespace granular::tool
