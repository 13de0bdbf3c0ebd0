#include "granular/model/chain_recipe.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "granular/io/text_hash.hpp"
#include "granular/model/centred_configuration.hpp"
#include "granular/model/configuration_file.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

// One lambda per alternative of a std::visit.
template <class... F>
struct Cases : F... {
  using F::operator()...;
};
template <class... F>
Cases(F...) -> Cases<F...>;  // Clang 14 does not deduce an aggregate's arguments (P1816) itself

// What identifies a types or radii file in a case: the values read from it (types as integers,
// radii to 17 digits, one a line; comments and spacing do not count), hashed (FNV-1a 64, hex).
// Its path alone would let a replay or resume read an edited file as the same chain.
std::string bead_file_hash(const ChainRecipe& c) {
  std::string text;
  char number[32];
  if (const auto* given = c.as<GivenTypes>())
    for (auto t : given->types) text += std::to_string(static_cast<int>(t)) + '\n';
  if (const auto* given = c.as<GivenRadii>())
    for (double r : given->radii) {
      std::snprintf(number, sizeof number, "%.17g\n", r);
      text += number;
    }
  std::snprintf(number, sizeof number, "%016llx", static_cast<unsigned long long>(text_hash(text)));
  return number;
}

// Refuses a file whose content no longer hashes to what the case recorded (older cases: no hash).
void check_bead_file(const ChainRecipe& c, const nlohmann::json& f, const std::string& name, const std::string& file) {
  const std::string key = name + "_hash";
  if (!f.contains(key)) return;
  const auto recorded = f.at(key).get<std::string>(), now = bead_file_hash(c);
  if (recorded != now)
    throw InvalidInput(name, " " + file + ": changed since the run was recorded (content hash " + recorded + ", now " +
                                 now + "); restore it, or start a new run");
}

ChainParameters parameters(const ChainRecipe& c, std::uint64_t r) {
  const TwoTypeDraw* draw = c.as<TwoTypeDraw>();
  return {.N = c.N,
          .q = draw ? draw->q : 0.5,
          .xi = c.xi(),
          .seed = c.seed,
          .realization = r,
          .F0 = c.F0,
          .R1 = c.R1,
          .material = c.material};
}

Chain with_walls(const std::vector<double>& radii, const ChainRecipe& c) {
  ChainSpec spec;
  spec.radii = radii;
  spec.materials = {c.material};
  spec.precompression = c.F0;
  if (c.walls == WallShape::sphere) {
    spec.left_wall.radius = radii.front();
    spec.right_wall.radius = radii.back();
  }
  return make_chain(spec);
}

void validate_r1(double r1) {
  if (!std::isfinite(r1) || r1 <= 0) throw InvalidInput("R1", " " + format_number(r1) + ": must be finite and > 0");
}

}  // namespace

const char* walls_description(WallShape walls) {
  return walls == WallShape::flat ? "flat, same material as the beads"
                                  : "fixed spheres, same radius and material as the end beads";
}

WallShape parse_wall_shape(const std::string& word) {
  if (word == "flat") return WallShape::flat;
  if (word == "sphere") return WallShape::sphere;
  throw InvalidInput("walls", " '" + word + "': must be flat or sphere");
}

TwoTypeDraw& ChainRecipe::draw() {
  if (auto* d = as<TwoTypeDraw>()) return *d;
  throw InvalidInput("chain", ": needs the two-type draw (disorder, q, xi), not another bead source");
}

const TwoTypeDraw& ChainRecipe::draw() const { return const_cast<ChainRecipe&>(*this).draw(); }

double ChainRecipe::xi() const {
  if (const auto* d = as<TwoTypeDraw>()) return d->xi;
  if (const auto* g = as<GivenTypes>()) return g->xi;
  return std::numeric_limits<double>::quiet_NaN();
}

std::size_t ChainRecipe::size() const {
  if (const auto* g = as<GivenTypes>()) return g->types.size();
  if (const auto* g = as<GivenRadii>()) return g->radii.size();
  return N;
}

Configuration ChainRecipe::types(std::uint64_t r) const {
  if (const auto* g = as<GivenTypes>()) return g->types;
  const auto* d = as<TwoTypeDraw>();
  if (!d) return {};
  return d->centred ? centred_configuration(d->disorder, d->q, N, seed, r)
                    : realization_configuration(d->disorder, d->q, N, seed, r);
}

std::vector<double> ChainRecipe::radii(std::uint64_t r) const {
  return std::visit(Cases{[&](const GivenRadii& g) { return g.radii; },
                          [&](const Quasiperiodic&) { return std::vector<double>(N, R1); },
                          [&](const BeadDistribution& d) { return realization_radii(d, N, seed, r); },
                          [&](const auto&) { return radii_of(types(r), R1, xi()); }},
                    source);
}

Chain ChainRecipe::chain_of(const Configuration& t) const {
  if (walls == WallShape::sphere) {
    from_types(t, parameters(*this, 0));  // its checks of the types, ξ and R1
    return with_walls(radii_of(t, R1, xi()), *this);
  }
  return from_types(t, parameters(*this, 0));
}

Chain ChainRecipe::chain(std::uint64_t r) const {
  if (const auto* quasi = as<Quasiperiodic>())
    return quasiperiodic_chain(*quasi, N, R1, F0, material, quasiperiodic_phase(*quasi, seed, r));
  if (typed()) return chain_of(types(r));
  return with_walls(radii(r), *this);
}

std::unique_ptr<BeadSource> ChainRecipe::beads(std::uint64_t r) const {
  if (const auto* g = as<GivenTypes>(); g && walls == WallShape::flat)
    return typed_beads(g->types, parameters(*this, r));
  // The streamed two-type sources know flat walls only; other walls come from the stored chain.
  if (!streamed()) return chain_beads(chain(r));
  return random_beads(draw().disorder, parameters(*this, r));
}

std::vector<double> ChainRecipe::possible_radii() const {
  const auto two_types = [&](bool one, bool two) {
    std::vector<double> out;
    if (one) out.push_back(R1);
    if (two) out.push_back(xi() * R1);
    return out;
  };
  return std::visit(
      Cases{[&](const GivenRadii& g) { return g.radii; }, [&](const Quasiperiodic&) { return std::vector<double>{R1}; },
            [&](const BeadDistribution& d) {
              std::vector<double> out;
              if (d.kind == BeadDistribution::Kind::types) {
                for (std::size_t t = 0; t < d.radii.size(); ++t)
                  if (d.probabilities[t] > 0) out.push_back(d.radii[t]);
                return out;
              }
              const bool uniform = d.kind == BeadDistribution::Kind::uniform;
              const double low = uniform ? d.low : d.minimum, high = uniform ? d.high : d.mean + 8 * d.sd;
              const int points = high > low ? 9 : 1;
              for (int i = 0; i < points; ++i)
                out.push_back(i == points - 1 ? high
                                              : low * std::pow(high / low, static_cast<double>(i) / (points - 1)));
              return out;
            },
            [&](const GivenTypes& g) {
              bool one = false, two = false;
              for (std::uint8_t t : g.types) (t == 1 ? one : two) = true;
              return two_types(one, two);
            },
            [&](const TwoTypeDraw& d) {
              return two_types(d.disorder == Disorder::homogeneous || d.disorder == Disorder::rdm2 || d.q > 0,
                               d.disorder == Disorder::rdm2 || (d.disorder != Disorder::homogeneous && d.q < 1));
            }},
      source);
}

std::string source_name(const ChainRecipe& c) {
  return std::visit(Cases{[](const TwoTypeDraw& d) { return to_string(d.disorder); },
                          [](const BeadDistribution& b) {
                            return std::string(b.kind == BeadDistribution::Kind::types ? "types" : "polydisperse");
                          },
                          [](const GivenTypes&) { return std::string("config"); },
                          [](const GivenRadii&) { return std::string("radii"); },
                          [](const Quasiperiodic& q) { return "quasi-" + to_string(q.kind); }},
                    c.source);
}

void validate(const ChainRecipe& c, std::size_t max_beads) {
  if (c.as<Quasiperiodic>() && c.walls != WallShape::flat)
    throw InvalidInput("walls", ": a quasiperiodic chain has its own walls (flat; fixed cylinders for the cylinders)");
  const std::size_t n = c.size();
  if (n < 2) throw InvalidInput("N", " " + std::to_string(n) + ": a chain needs at least 2 beads");
  if (n > max_beads)
    throw InvalidInput("N", " " + std::to_string(n) + ": more than " +
                                (max_beads == 100000000 ? std::string("1e8")
                                                        : format_number(static_cast<double>(max_beads))) +
                                " beads");
  if (!std::isfinite(c.F0) || c.F0 < 0)
    throw InvalidInput("F0", " " + format_number(c.F0) + ": must be finite and >= 0");
  validate(c.material, "material");
  std::visit(Cases{[&](const Quasiperiodic& q) {
                     validate_r1(c.R1);
                     validate(q, c.F0);
                     check_cylinder_contacts(q, c.R1, c.F0,
                                             c.material);  // refuses a line contact; warnings: plausibility
                   },
                   [&](const BeadDistribution& d) { validate(d); },
                   [&](const GivenRadii& g) {
                     for (std::size_t i = 0; i < g.radii.size(); ++i)
                       if (const double r = g.radii[i]; !std::isfinite(r) || r <= 0)  // make_chain's words
                         throw InvalidInput("radii", ": bead " + std::to_string(i + 1) + " has radius " +
                                                         format_number(r) + " m (must be finite and > 0)");
                   },
                   [&](const GivenTypes& g) {
                     validate_size_ratio(g.xi);
                     validate_r1(c.R1);
                   },
                   [&](const TwoTypeDraw& d) {
                     validate_size_ratio(d.xi);
                     validate_r1(c.R1);
                     validate_probability(d.q);
                   }},
             c.source);
}

nlohmann::json describe(const ChainRecipe& c, std::optional<std::uint64_t> realization) {
  nlohmann::json d;
  d["F0_N"] = c.F0;
  d["material"] = describe(c.material);
  d["walls"] = walls_description(c.walls);
  d["N"] = c.size();
  const auto drawn = [&] {
    d["seed"] = c.seed;
    if (realization) d["realization"] = *realization;
  };
  std::visit(Cases{[&](const Quasiperiodic& q) {
                     d["R1_m"] = c.R1;
                     d["quasiperiodic"] = describe(q);
                     drawn();
                     if (realization) d["phase_rad"] = quasiperiodic_phase(q, c.seed, *realization);
                   },
                   [&](const BeadDistribution& b) {
                     d["beads"] = describe(b);
                     drawn();
                   },
                   [&](const GivenRadii& g) {
                     if (!g.file.empty()) d["radii_file"] = g.file;
                   },
                   [&](const GivenTypes& g) {
                     d["R1_m"] = c.R1;
                     d["xi"] = g.xi;
                     if (!g.file.empty()) d["config_file"] = g.file;
                   },
                   [&](const TwoTypeDraw& t) {
                     d["R1_m"] = c.R1;
                     d["xi"] = t.xi;
                     d["disorder"] = to_string(t.disorder);
                     d["q"] = t.q;
                     drawn();
                   }},
             c.source);
  return d;
}

// A case spells every source's fields in one flat record (older readers expect disorder, q and
// xi in every case): the ones its source does not use are the draw's defaults.
void describe_fields(const ChainRecipe& c, nlohmann::json& f) {
  const TwoTypeDraw plain;
  const TwoTypeDraw* draw = c.as<TwoTypeDraw>();
  const auto* distribution = c.as<BeadDistribution>();
  const bool k_types = distribution && distribution->kind == BeadDistribution::Kind::types;
  f["disorder"] = to_string(draw ? draw->disorder : k_types ? distribution->rule : plain.disorder);
  f["q"] = draw ? draw->q : plain.q;
  f["xi"] = c.typed() ? c.xi() : plain.xi;
  f["N"] = c.size();
  f["F0_N"] = c.F0;
  f["R1_m"] = c.R1;
  f["seed"] = c.seed;
  f["material"] = describe(c.material);
  f["walls"] = walls_description(c.walls);
  if (distribution) f["beads"] = describe(*distribution);
  if (const auto* q = c.as<Quasiperiodic>()) f["quasiperiodic"] = describe(*q);
  if (draw && draw->centred) f["chain_draw"] = "outward from the centre bead";
  if (const auto* g = c.as<GivenTypes>(); g && !g->file.empty())
    f["config_file"] = g->file, f["config_file_hash"] = bead_file_hash(c);
  if (const auto* g = c.as<GivenRadii>(); g && !g->file.empty())
    f["radii_file"] = g->file, f["radii_file_hash"] = bead_file_hash(c);
}

ChainRecipe parse_recipe_fields(const nlohmann::json& f) {
  ChainRecipe c;
  try {
    TwoTypeDraw draw{.disorder = parse_disorder(f.at("disorder").get<std::string>()),
                     .q = f.at("q").get<double>(),
                     .xi = f.at("xi").get<double>(),
                     .centred = f.contains("chain_draw")};
    c.N = f.at("N").get<std::size_t>();
    c.F0 = f.at("F0_N").get<double>();
    c.R1 = f.at("R1_m").get<double>();
    c.seed = f.at("seed").get<std::uint64_t>();
    const auto& m = f.at("material");
    c.material = {m.at("E_Pa").get<double>(), m.at("nu").get<double>(), m.at("rho_kg_m3").get<double>()};
    const auto walls = f.at("walls").get<std::string>();
    if (walls == walls_description(WallShape::sphere)) c.walls = WallShape::sphere;
    else if (walls != walls_description(WallShape::flat))
      throw InvalidInput("walls", " '" + walls + "': not a description of flat or sphere walls");
    if (f.contains("beads")) c.source = parse_bead_distribution(f.at("beads").get<std::string>());
    else if (f.contains("quasiperiodic")) c.source = parse_quasiperiodic(f.at("quasiperiodic"));
    else if (f.contains("config_file")) {
      const auto file = f.at("config_file").get<std::string>();
      c.source = GivenTypes{.types = read_configuration_file(file), .xi = draw.xi, .file = file};
      check_bead_file(c, f, "config_file", file);
    } else if (f.contains("radii_file")) {
      const auto file = f.at("radii_file").get<std::string>();
      c.source = GivenRadii{.radii = read_radii_file(file), .file = file};
      check_bead_file(c, f, "radii_file", file);
    } else c.source = draw;
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInput("chain", std::string(": ") + e.what());
  }
  return c;
}

}  // namespace granular
