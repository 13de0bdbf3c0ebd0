#include "granular/case/chain_choices.hpp"

#include <utility>

#include "granular/error.hpp"
#include "granular/io/bead_distribution_syntax.hpp"
#include "granular/model/configuration_file.hpp"

namespace granular {

const ParameterTable<ChainChoices>& chain_parameters() {
  using O = ChainChoices;
  using P = Parameter<O>;
  static const ParameterTable<O> table{
      P{"disorder", &O::disorder, "h | A | RDM1 | RDM2 (homogeneous, Anderson, random dimer 1/2)"}.overridden(
          {"config", "radii", "polydisperse", "quasi"}),
      P{"xi", &O::xi, "size ratio R2/R1 in (0,1]"}.overridden(
          {"radii", "types", "type_masses", "polydisperse", "quasi", "disorder h homogeneous"}),
      P{"q", &O::q, "probability of a type-1 bead (A), dimer 11 (RDM1) or dimer 12 (RDM2), in [0,1]"}.overridden(
          {"config", "radii", "types", "type_masses", "polydisperse", "quasi", "disorder h homogeneous"}),
      P{"N", &O::n, "beads in the chain (>= 2)"}.overridden({"config", "radii"}),
      {"F0", &O::f0, "static precompression [N]"},
      P{"R1", &O::r1, "radius of type-1 beads [m] (steel beads and steel walls; `quasi`: of every bead or cylinder)"}
          .overridden({"radii", "types", "type_masses", "polydisperse"}),
      {"walls", &O::walls,
       "flat (the paper's) | sphere: fixed spheres of the end beads' radius and material, the textbook fixed-end "
       "lattice"},
      P{"seed", &O::seed, "random seed"}.overridden({"config", "radii", "disorder h homogeneous"}),
      P{"realization", &O::realization,
        "which realization of the seed (0-based; `quasi`: which phase, unless `phase` fixes it)"}
          .overridden({"config", "radii", "phase", "disorder h homogeneous"}),
      {"config", &O::config,
       "file with one bead type (1 or 2) per line, '#' comments; its length is the chain's (not with `N`, `disorder`, "
       "`q`, `seed`, `realization`)",
       false},
      {"radii", &O::radii,
       "file with one radius [m] per line, '#' comments; its length is the chain's (not with `N`, `disorder`, `q`, "
       "`xi`, `R1`, `seed`, "
       "`realization`)",
       false},
      {"types", &O::types,
       "k bead types 'R1:P1,R2:P2,...' (radius [m]: probability) drawn by `disorder` A (each bead), RDM1 (each "
       "dimer) or RDM2 (two types); not with `q`, `xi`, `R1`",
       false},
      {"type_masses", &O::type_masses, "as `types` with masses [kg] of steel spheres: 'M1:P1,M2:P2,...'", false},
      {"polydisperse", &O::polydisperse,
       "radii drawn per bead and realization: uniform:LO:HI or normal:MEAN:SD:MIN (truncated below at MIN) [m]", false},
      {"quasi", &O::quasi,
       "quasiperiodic chain: s1 (on-site springs), s2 (masses) or cylinders (crossing angles), modulated by 1 + "
       "modulation cos(2 pi ratio n + phase); R1 is the beads' radius",
       false},
      P{"modulation", &O::modulation, "`quasi`: relative modulation strength lambda, |lambda| < 1"}.needing("quasi"),
      P{"ratio", &O::ratio, "`quasi`: the incommensurate ratio beta > 0: golden, p/q or a number"}.needing("quasi"),
      P{"phase", &O::phase,
        "`quasi`: the phase [rad] (default: drawn uniformly in [0, 2 pi) per `seed` and `realization`)", false}
          .needing("quasi"),
      P{"angle", &O::angle, "`quasi` cylinders: mean crossing angle alpha0 [degrees] in (0, 180)"}.needing("quasi",
                                                                                                           {"cylinders",
                                                                                                            "c"}),
      P{"k0", &O::k0, "`quasi` s1: mean on-site stiffness in units of the bond stiffness K"}.needing("quasi", {"s1"}),
      P{"k0_n_per_m", &O::k0_n_per_m,
        "`quasi` s1: mean on-site stiffness [N/m] instead of `k0` (0: use `k0`); allows `F0` 0"}
          .needing("quasi", {"s1"})};
  return table;
}

namespace {

/// The draw's whole numbers as every chain takes them: N ≥ 2, seed ≥ 0 (N's upper limit is the
/// recipe's: validate(ChainRecipe) or a study's own).
void check_counts(const ChainChoices& o) {
  if (o.n < 2) throw InvalidInput("N", " " + std::to_string(o.n) + ": a chain needs at least 2 beads");
  if (o.seed < 0) throw InvalidInput("seed", " " + std::to_string(o.seed) + ": must be >= 0");
}

/// A chain comes from one source: refuses a second one given (the two named).
void require_one_source(const ChainChoices& o) {
  const std::pair<const char*, const std::string*> sources[]{{"config", &o.config},
                                                             {"radii", &o.radii},
                                                             {"types", &o.types},
                                                             {"type_masses", &o.type_masses},
                                                             {"polydisperse", &o.polydisperse},
                                                             {"quasi", &o.quasi}};
  const char* first = nullptr;
  for (const auto& [name, value] : sources)
    if (value->empty()) continue;
    else if (!first) first = name;
    else throw InvalidInput(name, std::string(": not with `") + first + "` (a chain comes from one of them)");
}

}  // namespace

std::optional<Quasiperiodic> quasiperiodic(const ChainChoices& o, const ChainChoices& defaults) {
  require_one_source(o);
  refuse_unmet_needs(o, chain_parameters(), defaults);  // `angle` with `quasi` s1 is refused, not ignored
  if (o.quasi.empty()) return std::nullopt;
  return Quasiperiodic{.kind = parse_quasi_kind(o.quasi),
                       .modulation = o.modulation,
                       .ratio = parse_ratio(o.ratio),
                       .phase = o.phase,
                       .angle = o.angle,
                       .k0 = o.k0,
                       .k0_n_per_m = o.k0_n_per_m};
}

std::optional<BeadDistribution> bead_distribution(const ChainChoices& o) {
  require_one_source(o);
  if (!o.types.empty()) return parse_bead_types(o.types, false, parse_disorder(o.disorder), "types");
  if (!o.type_masses.empty()) return parse_bead_types(o.type_masses, true, parse_disorder(o.disorder), "type_masses");
  if (!o.polydisperse.empty()) return parse_polydisperse(o.polydisperse, "polydisperse");
  return std::nullopt;
}

RadiusNames radius_names(const ChainChoices& o, const std::function<std::string(const std::string&)>& told) {
  const char* distribution = !o.types.empty() ? "types" : !o.type_masses.empty() ? "type_masses" : "polydisperse";
  return {told("R1"), told(distribution), told("radii"), told("angle"), told("modulation")};
}

StreamedChain stream_chain(const ChainChoices& o, const std::function<std::string(const std::string&)>& told,
                           const ChainChoices& defaults) {
  std::vector<std::string> file_warnings;
  const ChainRecipe recipe = chain_recipe(o, file_warnings, defaults);
  StreamedChain s = stream_chain(recipe, chain_realization(o), radius_names(o, told));
  s.warnings.insert(s.warnings.begin(), file_warnings.begin(), file_warnings.end());
  return s;
}

void set_study_draw(ChainRecipe& chain, const ChainChoices& o) {
  chain.draw().disorder = parse_disorder(o.disorder);
  chain.draw().q = o.q;
  check_counts(o);
  if (o.n > 100000000) throw InvalidInput("N", " " + std::to_string(o.n) + ": more than 1e8 beads");
  chain.N = static_cast<std::size_t>(o.n);
  chain.F0 = o.f0, chain.R1 = o.r1;
  chain.seed = static_cast<std::uint64_t>(o.seed);
  chain.walls = parse_wall_shape(o.walls);
}

ChainChoices chain_kind_choices(ChainChoices o) {
  const ChainChoices plain;
  o.q = plain.q, o.xi = plain.xi, o.n = plain.n, o.f0 = plain.f0, o.r1 = plain.r1;
  o.seed = plain.seed;
  return o;
}

ChainChoices chain_choices(const ChainRecipe& r) {
  const TwoTypeDraw& draw = r.draw();
  ChainChoices o;
  o.disorder = to_string(draw.disorder);
  o.q = draw.q, o.xi = draw.xi;
  o.f0 = r.F0, o.r1 = r.R1;
  o.n = static_cast<long long>(r.N), o.seed = static_cast<long long>(r.seed);
  o.walls = r.walls == WallShape::flat ? "flat" : "sphere";
  return o;
}

ChainRecipe chain_recipe(const ChainChoices& o, std::vector<std::string>& warnings, const ChainChoices& defaults) {
  check_counts(o);
  if (o.realization < 0) throw InvalidInput("realization", " " + std::to_string(o.realization) + ": must be >= 0");
  ChainRecipe r{.R1 = o.r1, .N = static_cast<std::size_t>(o.n), .F0 = o.f0, .seed = static_cast<std::uint64_t>(o.seed)};
  r.walls = parse_wall_shape(o.walls);
  if (auto quasi = quasiperiodic(o, defaults)) r.source = *quasi;
  else if (auto beads = bead_distribution(o)) r.source = *beads;
  else if (!o.config.empty())
    r.source = GivenTypes{.types = read_configuration_file(o.config), .xi = o.xi, .file = o.config};
  else if (!o.radii.empty()) r.source = GivenRadii{.radii = read_radii_file(o.radii, &warnings), .file = o.radii};
  else r.source = TwoTypeDraw{.disorder = parse_disorder(o.disorder), .q = o.q, .xi = o.xi, .centred = o.auto_n};
  if (o.auto_n && !r.as<TwoTypeDraw>())
    throw InvalidInput("N", ": a chain drawn from its centre (the automatic N) has two bead types, not a bead source");
  return r;
}

}  // namespace granular
