#pragma once
// The options `exponents` has beyond the paper's study: which chains (--chains,
// and a chain of the user's own from --types / --type-masses / --polydisperse, named by
// --chain-name, or a quasiperiodic chain from --quasi over phases), which kicks (--ic, and the mode of --ic mode:
// --mode / --near / --energy), and the maximal Lyapunov exponent (--mle). The same option words as `spreading`.
// The rule that makes a table of them, shared with Python: study/exponent_choices.hpp.
#include <string>

#include <CLI/CLI.hpp>

#include "chain_options.hpp"
#include "dynamics_options.hpp"
#include "granular/study/exponent_choices.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// The library's choices, bound straight to the flags: the table's kinds and kicks on the config
/// itself (--chains and --ic by their text forms: comma lists), the chain of one's own in words,
/// the mode of --ic mode on the base case.
inline void add_exponent_choices(CLI::App& app, ExponentChoices& o, ExponentTableConfig& config) {
  TransportCase& run = config.base;
  add_parameters(app, config, exponent_table_parameters(), {.only = {"chains", "ic"}});
  add_parameters(app, o, exponent_parameters(), {.only = {"types_rule"}});
  add_quasiperiodic_options(app, o.beads);
  add_bead_distribution_options(app, o.beads, "--types-rule");
  add_parameters(app, o, exponent_parameters(), {.only = {"chain_name"}});
  add_parameters(app, run.mode, mode_kick_parameters());
  add_mle_options(app, run,
                  "X1 at T, its ensemble mean (columns mle, mle_real_err: its standard error, mle_sd: spread over "
                  "realizations) and <X1(t)> in the curves");
}

}  // namespace granular::tool
