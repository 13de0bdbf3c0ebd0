#pragma once
// The options that pick one chain, shared by every single-chain tool:
// a random realization (--disorder --xi --q --N --seed --realization), a file of bead types
// (--config) or a file of radii (--radii), plus --F0 and --R1.
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "granular/model/centred_configuration.hpp"
#include "granular/model/configuration_file.hpp"
#include "granular/model/named_chains.hpp"
#include "tool_main.hpp"

namespace granular::tool {

struct ChainOptions {
  std::string disorder = "A";
  double xi = 0.5, q = 0.5, f0 = 10, r1 = paper_r1;
  long long n = 100, seed = 1, realization = 0;
  std::string config, radii;
  bool auto_n = false;         ///< --N auto (long_time_options.hpp): N from T, the chain drawn from its centre
  nlohmann::json length_rule;  ///< and the rule's numbers
};

inline void add_chain_options(CLI::App& app, ChainOptions& o) {
  app.add_option("--disorder", o.disorder, "h | A | RDM1 | RDM2 (homogeneous, Anderson, random dimer 1/2)")
      ->capture_default_str();
  app.add_option("--xi", o.xi, "size ratio R2/R1 in (0,1]")->capture_default_str();
  app.add_option("--q", o.q, "probability of a type-1 bead (A), dimer 11 (RDM1) or dimer 12 (RDM2), in [0,1]")
      ->capture_default_str();
  add_integer(app, "--N", o.n, "beads in the chain (>= 2)");
  app.add_option("--F0", o.f0, "static precompression [N]")->capture_default_str();
  app.add_option("--R1", o.r1, "radius of type-1 beads [m] (steel beads and flat steel walls)")->capture_default_str();
  add_integer(app, "--seed", o.seed, "random seed");
  add_integer(app, "--realization", o.realization, "which realization of the seed (0-based)");
  auto* config =
      app.add_option("--config", o.config,
                     "file with one bead type (1 or 2) per line, '#' comments; overrides --disorder/--q/--N");
  auto* radii = app.add_option("--radii", o.radii,
                               "file with one radius [m] per line, '#' comments; overrides --disorder/--q/--N/--xi");
  config->excludes(radii);
}

struct SelectedChain {
  Chain chain;
  Configuration types;  ///< empty when the chain came from a radii file
  nlohmann::json description;
};

/// What every chain the options pick shares: the seed and realization, checked, with the other
/// named-chain parameters (N unchecked: a stored and a streamed chain have their own limits).
inline ChainParameters chain_parameters(const ChainOptions& o) {
  if (o.seed < 0) throw InvalidInput("seed", " " + std::to_string(o.seed) + ": must be >= 0");
  if (o.realization < 0) throw InvalidInput("realization", " " + std::to_string(o.realization) + ": must be >= 0");
  return {.N = static_cast<std::size_t>(o.n),
          .q = o.q,
          .xi = o.xi,
          .seed = static_cast<std::uint64_t>(o.seed),
          .realization = static_cast<std::uint64_t>(o.realization),
          .F0 = o.f0,
          .R1 = o.r1};
}

/// The "chain" entry of a tool's JSON: F0, material, walls and what picked the chain (a radii
/// file; R1, ξ and a types file or the disorder, q, seed and realization). N is added by the caller.
inline nlohmann::json chain_description(const ChainOptions& o) {
  nlohmann::json d;
  d["F0_N"] = o.f0;
  d["material"] = {{"E_Pa", steel.young}, {"nu", steel.poisson}, {"rho_kg_m3", steel.density}};
  d["walls"] = "flat, same material as the beads";
  if (!o.radii.empty()) {
    d["radii_file"] = o.radii;
    return d;
  }
  d["R1_m"] = o.r1;
  d["xi"] = o.xi;
  if (!o.config.empty()) {
    d["config_file"] = o.config;
    return d;
  }
  d["disorder"] = to_string(parse_disorder(o.disorder));
  d["q"] = o.q;
  d["seed"] = o.seed;
  d["realization"] = o.realization;
  return d;
}

inline SelectedChain build_chain(const ChainOptions& o) {
  ChainParameters p = chain_parameters(o);
  if (o.n < 2) throw InvalidInput("N", " " + std::to_string(o.n) + ": a chain needs at least 2 beads");
  SelectedChain s;
  s.description = chain_description(o);
  if (!o.radii.empty()) {
    if (!std::isfinite(o.f0) || o.f0 < 0)
      throw InvalidInput("F0", " " + format_number(o.f0) + ": must be finite and >= 0");
    s.chain = from_radii(read_radii_file(o.radii), o.f0);
  } else {
    if (!o.config.empty()) {
      p.N = 2;  // from the file
      validate(p);
      s.types = read_configuration_file(o.config);
    } else {
      validate(p);
      s.types = o.auto_n ? centred_configuration(parse_disorder(o.disorder), o.q, p.N, p.seed, p.realization)
                         : realization_configuration(parse_disorder(o.disorder), o.q, p.N, p.seed, p.realization);
    }
    s.chain = from_types(s.types, p);
  }
  s.description["N"] = s.chain.size();
  if (o.auto_n) s.description["N_rule"] = o.length_rule;
  return s;
}

}  // namespace granular::tool
