#pragma once
// The options that pick one chain (a ChainRecipe and its realization), shared by every
// single-chain tool: a random two-type draw, a types or radii file, k types, polydisperse radii or
// a quasiperiodic chain; stored, or streamed for tools that walk it once (localization).
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "granular/model/selected_chain.hpp"
#include "granular/study/chain_choices.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// The chain's options bind straight into the library's choices (study/chain_choices.hpp).
using ChainOptions = ChainChoices;

/// --types, --type-masses, --polydisperse (mutually exclusive); returns them for more exclusions.
/// `rule_flag`: the tool's flag that says how types are drawn.
inline std::vector<CLI::Option*> add_bead_distribution_options(CLI::App& app, ChainOptions& o,
                                                               const std::string& rule_flag = "--disorder") {
  auto* types = app.add_option("--types", o.types,
                               "k bead types 'R1:P1,R2:P2,...' (radius [m]: probability) drawn by " + rule_flag +
                                   " A (each bead), RDM1 (each dimer) or RDM2 (two types); overrides --q/--xi/--R1");
  auto* masses =
      app.add_option("--type-masses", o.type_masses, "as --types with masses [kg] of steel spheres: 'M1:P1,M2:P2,...'");
  auto* poly = app.add_option("--polydisperse", o.polydisperse,
                              "radii drawn per bead and realization: uniform:LO:HI or normal:MEAN:SD:MIN (truncated "
                              "below at MIN) [m]");
  const std::vector<CLI::Option*> all{types, masses, poly};
  for (auto* a : all)
    for (auto* b : all)
      if (a != b) a->excludes(b);
  return all;
}

/// --walls flat | sphere (model/chain_recipe.hpp: WallShape).
inline void add_walls_option(CLI::App& app, std::string& walls) {
  add_option(app, "--walls", walls,
             "flat (the paper's) | sphere: fixed spheres of the end beads' radius and material, the textbook "
             "fixed-end lattice");
}

/// --quasi and its parameters (model/quasiperiodic.hpp); returns --quasi for exclusions.
inline CLI::Option* add_quasiperiodic_options(CLI::App& app, ChainOptions& o) {
  using O = ChainOptions;
  add_flags<O>(
      app, o,
      {{"--quasi", &O::quasi,
        "quasiperiodic chain: s1 (on-site springs), s2 (masses) or cylinders (crossing angles), modulated by 1 + "
        "modulation cos(2 pi ratio n + phase); R1 is the beads' radius",
        false},
       {"--modulation", &O::modulation, "--quasi: relative modulation strength lambda, |lambda| < 1"},
       {"--ratio", &O::ratio, "--quasi: the incommensurate ratio beta > 0: golden, p/q or a number"},
       {"--phase", &O::phase,
        "--quasi: the phase [rad] (default: drawn uniformly in [0, 2 pi) per --seed and --realization)", false},
       {"--angle", &O::angle, "--quasi cylinders: mean crossing angle alpha0 [degrees] in (0, 180)"},
       {"--k0", &O::k0, "--quasi s1: mean on-site stiffness in units of the bond stiffness K"},
       {"--k0-n-per-m", &O::k0_n_per_m,
        "--quasi s1: mean on-site stiffness [N/m] instead of --k0 (0: use --k0); allows --F0 0"}});
  return app.get_option("--quasi");
}

inline void add_chain_options(CLI::App& app, ChainOptions& o) {
  add_option(app, "--disorder", o.disorder, "h | A | RDM1 | RDM2 (homogeneous, Anderson, random dimer 1/2)");
  add_option(app, "--xi", o.xi, "size ratio R2/R1 in (0,1]");
  add_option(app, "--q", o.q, "probability of a type-1 bead (A), dimer 11 (RDM1) or dimer 12 (RDM2), in [0,1]");
  add_integer(app, "--N", o.n, "beads in the chain (>= 2)");
  add_option(app, "--F0", o.f0, "static precompression [N]");
  add_option(app, "--R1", o.r1, "radius of type-1 beads [m] (steel beads and steel walls)");
  add_walls_option(app, o.walls);
  add_integer(app, "--seed", o.seed, "random seed");
  add_integer(app, "--realization", o.realization, "which realization of the seed (0-based)");
  auto* config =
      app.add_option("--config", o.config,
                     "file with one bead type (1 or 2) per line, '#' comments; overrides --disorder/--q/--N");
  auto* radii = app.add_option("--radii", o.radii,
                               "file with one radius [m] per line, '#' comments; overrides --disorder/--q/--N/--xi");
  config->excludes(radii);
  auto* quasi = add_quasiperiodic_options(app, o);
  for (auto* a : add_bead_distribution_options(app, o))
    for (auto* b : {config, radii, quasi}) a->excludes(b), b->excludes(a);
  for (auto* b : {config, radii}) quasi->excludes(b), b->excludes(quasi);
}

/// The recipe the options pick (granular::chain_recipe), a radii file's warnings printed.
inline ChainRecipe chain_recipe(const ChainOptions& o) {
  std::vector<std::string> warnings;
  ChainRecipe r = granular::chain_recipe(o, warnings);
  warn(warnings);
  return r;
}

/// The options named in the warnings about implausible radii (model/plausibility.hpp): those that
/// set R1, the bead distribution and the radii file.
inline RadiusNames radius_options(const ChainOptions& o) {
  const std::string distribution = !o.types.empty()         ? "--types"
                                   : !o.type_masses.empty() ? "--type-masses"
                                                            : "--polydisperse";
  return {"--R1", distribution, "--radii"};
}

/// The chain the options pick, streamed (granular::stream_chain), its warnings printed.
inline StreamedChain stream_chain(const ChainOptions& o) {
  StreamedChain s = granular::stream_chain(chain_recipe(o), chain_realization(o), radius_options(o));
  warn(s.warnings);
  return s;
}

}  // namespace granular::tool
