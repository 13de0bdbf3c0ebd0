#pragma once
// The options `exponents` has beyond the paper's study: which chains (--chains,
// and a chain of the user's own from --types / --type-masses / --polydisperse, named by
// --chain-name, or a quasiperiodic chain from --quasi over phases), which kicks (--ic, and the mode of --ic mode:
// --mode / --mode-khz / --energy), and the maximal Lyapunov exponent (--mle). The same option words as `spreading`.
// The rule that makes a table of them, shared with Python: study/exponent_choices.hpp.
#include <string>

#include <CLI/CLI.hpp>

#include "chain_options.hpp"
#include "dynamics_options.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/study/exponent_choices.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// The library's choices, bound straight to the flags, but the lists of --chains and --ic, read as
/// text, and the mode of a mode kick.
struct ExponentOptions : ExponentChoices {
  std::string chains_text = "h,A,RDM1,RDM2", kicks_text = "displacement,velocity";
  ModeKick mode;
  /// The library's choices, the lists parsed.
  ExponentChoices choices() const {
    ExponentChoices c = *this;
    c.chains = parse_word_list(chains_text, "chains");
    c.ic = parse_word_list(kicks_text, "ic");
    return c;
  }
};

inline void add_exponent_choices(CLI::App& app, ExponentOptions& o, BeyondOptions& beyond) {
  add_option(app, "--chains", o.chains_text,
             "chain kinds: comma list of h, A, RDM1, RDM2, or 'none' (only the chain of --types/--polydisperse)");
  add_option(app, "--ic", o.kicks_text, "kicks: comma list of displacement, velocity, mode (--mode or --mode-khz)");
  auto* quasi = add_quasiperiodic_options(app, o.beads);
  for (auto* a : add_bead_distribution_options(app, o.beads, "--types-rule")) a->excludes(quasi), quasi->excludes(a);
  app.add_option("--types-rule", o.types_rule,
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
inline void apply(const ExponentOptions& o, ExponentTableConfig& config) {
  granular::apply(o.choices(), config);
  apply(o.mode, config.kicks, config.base);
}

}  // namespace granular::tool
