#pragma once
// The chain options of tools that stream a chain instead of building it (localization): the
// same flags as chain_options.hpp, but --N is a number (1e7 is accepted) and a random
// realization is drawn a piece at a time, so N can be 10⁸ with memory independent of N.
// --config and --radii files are read whole (they are O(N) on disk anyway).
#include <cmath>
#include <memory>
#include <string>

#include "chain_options.hpp"
#include "granular/model/bead_source.hpp"

namespace granular::tool {

struct StreamedChain {
  std::unique_ptr<BeadSource> source;
  nlohmann::json description;
};

/// Registers the chain options of chain_options.hpp with --N re-bound to `n` (a number).
inline void add_streamed_chain_options(CLI::App& app, ChainOptions& o, double& n) {
  add_chain_options(app, o);
  app.remove_option(app.get_option("--N"));
  app.add_option("--N", n, "beads in the chain, 2 ... 1e12 (1e7 accepted); memory does not grow with N")
      ->capture_default_str();
}

inline StreamedChain build_bead_source(const ChainOptions& o, double n) {
  if (!std::isfinite(o.f0) || o.f0 <= 0)
    throw InvalidInput("--F0 " + format_number(o.f0) + ": must be finite and > 0 (the sonic vacuum has no linear limit)");
  if (!std::isfinite(o.r1) || o.r1 <= 0) throw InvalidInput("--R1 " + format_number(o.r1) + ": must be finite and > 0");
  StreamedChain s;
  nlohmann::json& d = s.description;
  d["F0_N"] = o.f0;
  d["material"] = {{"E_Pa", steel.young}, {"nu", steel.poisson}, {"rho_kg_m3", steel.density}};
  d["walls"] = "flat, same material as the beads";
  if (!o.radii.empty()) {
    s.source = chain_beads(make_chain(read_radii_file(o.radii), o.f0));
    d["radii_file"] = o.radii;
  } else {
    validate_size_ratio(o.xi);
    const BidisperseBeads beads{o.r1, o.xi, o.f0, steel};
    d["R1_m"] = o.r1;
    d["xi"] = o.xi;
    if (!o.config.empty()) {
      s.source = typed_beads(read_configuration_file(o.config), beads);
      d["config_file"] = o.config;
    } else {
      const Disorder kind = parse_disorder(o.disorder);
      validate_probability(o.q);
      if (!(n >= 2) || !(n <= 1e12) || n != std::floor(n))
        throw InvalidInput("--N " + format_number(n) + ": must be a whole number of beads in [2, 1e12]");
      if (o.seed < 0) throw InvalidInput("--seed " + std::to_string(o.seed) + ": must be >= 0");
      if (o.realization < 0) throw InvalidInput("--realization " + std::to_string(o.realization) + ": must be >= 0");
      s.source = random_beads(kind, o.q, static_cast<std::size_t>(n), static_cast<std::uint64_t>(o.seed),
                              static_cast<std::uint64_t>(o.realization), beads);
      d["disorder"] = to_string(kind);
      d["q"] = o.q;
      d["seed"] = o.seed;
      d["realization"] = o.realization;
    }
  }
  d["N"] = s.source->size();
  return s;
}

}  // namespace granular::tool
