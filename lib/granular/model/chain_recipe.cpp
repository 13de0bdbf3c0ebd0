#include "granular/model/chain_recipe.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "granular/io/text_hash.hpp"
#include "granular/model/centred_configuration.hpp"
#include "granular/model/configuration_file.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

// What identifies a types or radii file in a case: the values read from it (types as integers,
// radii to 17 digits, one a line; comments and spacing do not count), hashed (FNV-1a 64, hex).
// Its path alone would let a replay or resume read an edited file as the same chain.
std::string bead_file_hash(const ChainRecipe& c) {
  std::string text;
  char number[32];
  if (c.given_types)
    for (auto t : *c.given_types) text += std::to_string(static_cast<int>(t)) + '\n';
  if (c.given_radii)
    for (double r : *c.given_radii) {
      std::snprintf(number, sizeof number, "%.17g\n", r);
      text += number;
    }
  std::snprintf(number, sizeof number, "%016llx", static_cast<unsigned long long>(text_hash(text)));
  return number;
}

// Refuses a file whose content no longer hashes to what the case recorded (older cases: no hash).
void check_bead_file(const ChainRecipe& c, const nlohmann::json& f, const std::string& name) {
  const std::string key = name + "_hash";
  if (!f.contains(key)) return;
  const auto recorded = f.at(key).get<std::string>(), now = bead_file_hash(c);
  if (recorded != now)
    throw InvalidInput(name, " " + c.source + ": changed since the run was recorded (content hash " + recorded +
                                 ", now " + now + "); restore it, or start a new run");
}

ChainParameters parameters(const ChainRecipe& c, std::uint64_t r) {
  return {
      .N = c.N, .q = c.q, .xi = c.xi, .seed = c.seed, .realization = r, .F0 = c.F0, .R1 = c.R1, .material = c.material};
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

std::size_t ChainRecipe::size() const {
  if (given_types) return given_types->size();
  if (given_radii) return given_radii->size();
  return N;
}

Configuration ChainRecipe::types(std::uint64_t r) const {
  if (given_types) return *given_types;
  if (given_radii || distribution || quasi) return {};
  return centred ? centred_configuration(disorder, q, N, seed, r) : realization_configuration(disorder, q, N, seed, r);
}

std::vector<double> ChainRecipe::radii(std::uint64_t r) const {
  if (given_radii) return *given_radii;
  if (quasi) return std::vector<double>(N, R1);
  if (distribution) return realization_radii(*distribution, N, seed, r);
  return radii_of(types(r), R1, xi);
}

Chain ChainRecipe::chain_of(const Configuration& t) const {
  if (walls == WallShape::sphere) {
    from_types(t, parameters(*this, 0));  // its checks of the types, ξ and R1
    return with_walls(radii_of(t, R1, xi), *this);
  }
  return from_types(t, parameters(*this, 0));
}

Chain ChainRecipe::chain(std::uint64_t r) const {
  if (quasi) return quasiperiodic_chain(*quasi, N, R1, F0, material, quasiperiodic_phase(*quasi, seed, r));
  if (given_radii || distribution) return with_walls(radii(r), *this);
  return chain_of(types(r));
}

std::unique_ptr<BeadSource> ChainRecipe::beads(std::uint64_t r) const {
  if (given_types && walls == WallShape::flat) return typed_beads(*given_types, parameters(*this, r));
  // The streamed two-type sources know flat walls only; other walls come from the stored chain.
  if (given_radii || distribution || centred || quasi || walls != WallShape::flat) return chain_beads(chain(r));
  return random_beads(disorder, parameters(*this, r));
}

std::vector<double> ChainRecipe::possible_radii() const {
  std::vector<double> out;
  if (given_radii) return *given_radii;
  if (quasi) return {R1};
  if (distribution && distribution->kind == BeadDistribution::Kind::types) {
    for (std::size_t t = 0; t < distribution->radii.size(); ++t)
      if (distribution->probabilities[t] > 0) out.push_back(distribution->radii[t]);
    return out;
  }
  if (distribution) {
    const bool uniform = distribution->kind == BeadDistribution::Kind::uniform;
    const double low = uniform ? distribution->low : distribution->minimum;
    const double high = uniform ? distribution->high : distribution->mean + 8 * distribution->sd;
    const int points = high > low ? 9 : 1;
    for (int i = 0; i < points; ++i)
      out.push_back(i == points - 1 ? high : low * std::pow(high / low, static_cast<double>(i) / (points - 1)));
    return out;
  }
  bool one = false, two = false;
  if (given_types) {
    for (std::uint8_t t : *given_types) (t == 1 ? one : two) = true;
  } else {
    two = disorder == Disorder::rdm2 || (disorder != Disorder::homogeneous && q < 1);
    one = disorder == Disorder::homogeneous || disorder == Disorder::rdm2 || q > 0;
  }
  if (one) out.push_back(R1);
  if (two) out.push_back(xi * R1);
  return out;
}

void validate(const ChainRecipe& c, std::size_t max_beads) {
  if (c.given_types && c.given_radii) throw InvalidInput("radii", ": a chain has given types or given radii, not both");
  if (c.distribution && !c.drawn())
    throw InvalidInput("beads", ": a bead distribution draws its chain; not with given types or radii");
  if (c.centred && (c.distribution || !c.drawn()))
    throw InvalidInput("N", ": a chain drawn from its centre (the automatic N) has two bead types, not a bead source");
  if (c.quasi && (c.distribution || !c.drawn() || c.centred))
    throw InvalidInput("quasi",
                       ": a quasiperiodic chain makes its own beads; not with a bead distribution, given types or "
                       "radii, or a centred draw");
  if (c.quasi && c.walls != WallShape::flat)
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
  if (c.quasi) {
    if (!std::isfinite(c.R1) || c.R1 <= 0)
      throw InvalidInput("R1", " " + format_number(c.R1) + ": must be finite and > 0");
    validate(*c.quasi, c.F0);
    check_cylinder_contacts(*c.quasi, c.R1, c.F0, c.material);  // refuses a line contact; warnings: plausibility
    return;
  }
  if (c.distribution) {
    validate(*c.distribution);
    return;
  }
  if (c.given_radii) {
    for (std::size_t i = 0; i < c.given_radii->size(); ++i)
      if (const double r = (*c.given_radii)[i]; !std::isfinite(r) || r <= 0)  // make_chain's words
        throw InvalidInput("radii", ": bead " + std::to_string(i + 1) + " has radius " + format_number(r) +
                                        " m (must be finite and > 0)");
    return;
  }
  validate_size_ratio(c.xi);
  if (!std::isfinite(c.R1) || c.R1 <= 0)
    throw InvalidInput("R1", " " + format_number(c.R1) + ": must be finite and > 0");
  if (!c.given_types) validate_probability(c.q);
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
  if (c.quasi) {
    d["R1_m"] = c.R1;
    d["quasiperiodic"] = describe(*c.quasi);
    drawn();
    if (realization) d["phase_rad"] = quasiperiodic_phase(*c.quasi, c.seed, *realization);
  } else if (c.distribution) {
    d["beads"] = describe(*c.distribution);
    drawn();
  } else if (c.given_radii) {
    if (!c.source.empty()) d["radii_file"] = c.source;
  } else {
    d["R1_m"] = c.R1;
    d["xi"] = c.xi;
    if (c.given_types) {
      if (!c.source.empty()) d["config_file"] = c.source;
    } else {
      d["disorder"] = to_string(c.disorder);
      d["q"] = c.q;
      drawn();
    }
  }
  return d;
}

void describe_fields(const ChainRecipe& c, nlohmann::json& f) {
  f["disorder"] = to_string(c.disorder);
  f["q"] = c.q;
  f["xi"] = c.xi;
  f["N"] = c.size();
  f["F0_N"] = c.F0;
  f["R1_m"] = c.R1;
  f["seed"] = c.seed;
  f["material"] = describe(c.material);
  f["walls"] = walls_description(c.walls);
  if (c.distribution) f["beads"] = describe(*c.distribution);
  if (c.quasi) f["quasiperiodic"] = describe(*c.quasi);
  if (c.centred) f["chain_draw"] = "outward from the centre bead";
  if (c.given_types && !c.source.empty()) f["config_file"] = c.source, f["config_file_hash"] = bead_file_hash(c);
  if (c.given_radii && !c.source.empty()) f["radii_file"] = c.source, f["radii_file_hash"] = bead_file_hash(c);
}

ChainRecipe parse_recipe_fields(const nlohmann::json& f) {
  ChainRecipe c;
  try {
    c.disorder = parse_disorder(f.at("disorder").get<std::string>());
    c.q = f.at("q").get<double>();
    c.xi = f.at("xi").get<double>();
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
    if (f.contains("beads")) c.distribution = parse_bead_distribution(f.at("beads").get<std::string>());
    if (f.contains("chain_draw")) c.centred = true;
    if (f.contains("quasiperiodic")) c.quasi = parse_quasiperiodic(f.at("quasiperiodic"));
    if (f.contains("config_file")) {
      c.source = f.at("config_file").get<std::string>();
      c.given_types = read_configuration_file(c.source);
      check_bead_file(c, f, "config_file");
    }
    if (f.contains("radii_file")) {
      c.source = f.at("radii_file").get<std::string>();
      c.given_radii = read_radii_file(c.source);
      check_bead_file(c, f, "radii_file");
    }
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInput("chain", std::string(": ") + e.what());
  }
  return c;
}

}  // namespace granular
