#pragma once
// The options `exponents` has beyond the paper's study: which chains (--chains,
// and a chain of the user's own from --types / --type-masses / --polydisperse, named by
// --chain-name, or a quasiperiodic chain from --quasi over phases), which kicks (--ic, and the mode of --ic mode:
// --mode / --mode-khz / --energy), and the maximal Lyapunov exponent (--mle). The same option words as `spreading`.
#include <string>

#include <CLI/CLI.hpp>

#include "chain_options.hpp"
#include "dynamics_options.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/study/exponent_table.hpp"
#include "tool_main.hpp"

namespace granular::tool {

struct ExponentChoices {
  std::string chains = "h,A,RDM1,RDM2", kicks = "displacement,velocity";
  /// Only its --types / --type-masses / --polydisperse, and `disorder`: --types-rule (empty: not given).
  ChainOptions beads = [] {
    ChainOptions o;
    o.disorder.clear();
    return o;
  }();
  std::string chain_name;  ///< the user's chain in the outputs; empty: "types" or "polydisperse"
  ModeKick mode;
};

inline void add_exponent_choices(CLI::App& app, ExponentChoices& o, BeyondOptions& beyond) {
  add_option(app, "--chains", o.chains,
             "chain kinds: comma list of h, A, RDM1, RDM2, or 'none' (only the chain of --types/--polydisperse)");
  add_option(app, "--ic", o.kicks, "kicks: comma list of displacement, velocity, mode (--mode or --mode-khz)");
  auto* quasi = add_quasiperiodic_options(app, o.beads);
  for (auto* a : add_bead_distribution_options(app, o.beads, "--types-rule")) a->excludes(quasi), quasi->excludes(a);
  app.add_option("--types-rule", o.beads.disorder,
                 "how --types/--type-masses are drawn: A (each bead, the default), RDM1 (each dimer), RDM2 (two "
                 "types: dimers 12 or 21)");
  app.add_option("--chain-name", o.chain_name,
                 "the name of the chain of --types/--type-masses/--polydisperse/--quasi in the outputs (its "
                 "'disorder' column; default: types, polydisperse or quasi-KIND); it runs after the --chains kinds, "
                 "R realizations (R phases for --quasi without --phase)");
  add_mode_kick_options(app, o.mode);
  add_mle_options(app, beyond,
                  "X1 at T, its ensemble mean (columns mle, mle_real_err: its standard error, mle_sd: spread over "
                  "realizations) and <X1(t)> in the curves");
}

/// The chains and kicks of the study into `config` (config.base then holds the mode kick).
inline void apply(const ExponentChoices& o, ExponentTableConfig& config) {
  config.chains.clear();
  if (o.chains != "none")
    for (const auto& name : parse_word_list(o.chains, "--chains")) config.chains.push_back(parse_disorder(name));
  config.kicks.clear();
  for (const auto& name : parse_word_list(o.kicks, "--ic")) config.kicks.push_back(parse_kick(name));
  config.bead_chains.clear();
  ChainOptions drawn = o.beads;
  if (!drawn.disorder.empty() && drawn.types.empty() && drawn.type_masses.empty())
    throw InvalidInput("--types-rule '" + drawn.disorder + "': only with --types or --type-masses");
  if (drawn.disorder.empty()) drawn.disorder = "A";
  try {
    parse_disorder(drawn.disorder);
  } catch (const InvalidInput&) {  // told here: the tool tells the library's `disorder` as --chains
    throw InvalidInput("--types-rule '" + drawn.disorder + "': expected A, RDM1 or RDM2");
  }
  if (const auto q = quasiperiodic(drawn)) {
    config.bead_chains.push_back({o.chain_name.empty() ? "quasi-" + to_string(q->kind) : o.chain_name, {}, *q});
  } else if (const auto beads = bead_distribution(drawn)) {
    const bool types = beads->kind == BeadDistribution::Kind::types;
    config.bead_chains.push_back({o.chain_name.empty() ? (types ? "types" : "polydisperse") : o.chain_name, *beads});
  } else if (!o.chain_name.empty()) {
    throw InvalidInput("--chain-name '" + o.chain_name +
                       "': only with --types, --type-masses, --polydisperse or --quasi");
  }
  apply(o.mode, config.kicks, config.base);
  validate(config);
}

}  // namespace granular::tool
