#pragma once
// The options that pick one chain (a ChainRecipe and its realization), shared by every
// single-chain tool: a random two-type draw, a types or radii file, k types, polydisperse radii or
// a quasiperiodic chain; stored, or streamed for tools that walk it once (localization).
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "granular/io/bead_distribution_syntax.hpp"
#include "granular/model/bead_distribution.hpp"
#include "granular/model/chain_recipe.hpp"
#include "granular/model/configuration_file.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/model/selected_chain.hpp"
#include "tool_main.hpp"

namespace granular::tool {

struct ChainOptions {
  std::string disorder = "A";
  double xi = 0.5, q = 0.5, f0 = 10, r1 = paper_r1;
  long long n = 100, seed = 1, realization = 0;
  std::string config, radii, types, type_masses, polydisperse, walls = "flat";
  std::string quasi, ratio = "golden";  ///< --quasi KIND, --ratio β
  double modulation = 0, angle = 45, k0 = 4, k0_n_per_m = 0;
  std::optional<double> phase;
  bool auto_n = false;  ///< --N auto (long_time_options.hpp): N from T, the chain drawn from its centre
};

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

/// The quasiperiodic chain the options pick, if --quasi is given.
inline std::optional<Quasiperiodic> quasiperiodic(const ChainOptions& o) {
  if (o.quasi.empty()) return std::nullopt;
  return Quasiperiodic{.kind = parse_quasi_kind(o.quasi),
                       .modulation = o.modulation,
                       .ratio = parse_ratio(o.ratio),
                       .phase = o.phase,
                       .angle = o.angle,
                       .k0 = o.k0,
                       .k0_n_per_m = o.k0_n_per_m};
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

/// The distribution of --types / --type-masses / --polydisperse, if one is given (rule: --disorder).
inline std::optional<BeadDistribution> bead_distribution(const ChainOptions& o) {
  if (!o.types.empty()) return parse_bead_types(o.types, false, parse_disorder(o.disorder), "--types");
  if (!o.type_masses.empty()) return parse_bead_types(o.type_masses, true, parse_disorder(o.disorder), "--type-masses");
  if (!o.polydisperse.empty()) return parse_polydisperse(o.polydisperse, "--polydisperse");
  return std::nullopt;
}

/// Reads a radii file, printing a warning for each implausible radius (file and line named).
inline std::vector<double> read_radii_warning(const std::string& path) {
  std::vector<std::string> warnings;
  std::vector<double> radii = read_radii_file(path, &warnings);
  warn(warnings);
  return radii;
}

/// The recipe the options pick, files read (not yet validated: a streamed chain has its own
/// limits). Seed and realization are checked here, as flags.
inline ChainRecipe chain_recipe(const ChainOptions& o) {
  if (o.seed < 0) throw InvalidInput("seed", " " + std::to_string(o.seed) + ": must be >= 0");
  if (o.realization < 0) throw InvalidInput("realization", " " + std::to_string(o.realization) + ": must be >= 0");
  if (o.n < 2) throw InvalidInput("N", " " + std::to_string(o.n) + ": a chain needs at least 2 beads");
  ChainRecipe r{.disorder = parse_disorder(o.disorder),
                .q = o.q,
                .xi = o.xi,
                .R1 = o.r1,
                .centred = o.auto_n,
                .N = static_cast<std::size_t>(o.n),
                .F0 = o.f0,
                .seed = static_cast<std::uint64_t>(o.seed)};
  r.walls = parse_wall_shape(o.walls);
  r.distribution = bead_distribution(o);
  if (!o.config.empty()) r.given_types = read_configuration_file(r.source = o.config);
  if (!o.radii.empty()) r.given_radii = read_radii_warning(r.source = o.radii);
  r.quasi = quasiperiodic(o);
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

/// The realization the options pick (0-based).
inline std::uint64_t chain_realization(const ChainOptions& o) { return static_cast<std::uint64_t>(o.realization); }

/// The chain the options pick, built and described.
inline SelectedChain build_chain(const ChainOptions& o) {
  SelectedChain s = granular::select_chain(chain_recipe(o), chain_realization(o), radius_options(o));
  warn(s.warnings);
  return s;
}

/// The chain the options pick, streamed (granular::stream_chain), its warnings printed.
inline StreamedChain stream_chain(const ChainOptions& o) {
  StreamedChain s = granular::stream_chain(chain_recipe(o), chain_realization(o), radius_options(o));
  warn(s.warnings);
  return s;
}

}  // namespace granular::tool
