#pragma once
// The chain of chain_options.hpp (same flags) as a bead source, for tools that walk a chain once
// instead of storing it (localization): a random realization is drawn a piece at a time, so N
// can be far beyond the 1e8 beads of a stored chain with memory independent of N. --config and
// --radii files are read whole (they are O(N) on disk anyway).
#include <memory>
#include <string>

#include "chain_options.hpp"
#include "granular/model/bead_source.hpp"

namespace granular::tool {

struct StreamedChain {
  std::unique_ptr<BeadSource> source;
  nlohmann::json description;
};

inline StreamedChain build_bead_source(const ChainOptions& o) {
  if (o.seed < 0) throw InvalidInput("seed", " " + std::to_string(o.seed) + ": must be >= 0");
  if (o.realization < 0) throw InvalidInput("realization", " " + std::to_string(o.realization) + ": must be >= 0");
  if (o.n < 2 || o.n > 1000000000000) throw InvalidInput("N", " " + std::to_string(o.n) + ": must be in [2, 1e12]");
  const ChainParameters p{.N = static_cast<std::size_t>(o.n),
                          .q = o.q,
                          .xi = o.xi,
                          .seed = static_cast<std::uint64_t>(o.seed),
                          .realization = static_cast<std::uint64_t>(o.realization),
                          .F0 = o.f0,
                          .R1 = o.r1};
  StreamedChain s;
  nlohmann::json& d = s.description;
  d["F0_N"] = o.f0;
  d["material"] = {{"E_Pa", steel.young}, {"nu", steel.poisson}, {"rho_kg_m3", steel.density}};
  d["walls"] = "flat, same material as the beads";
  if (const auto beads = bead_distribution(o)) {  // stored: memory O(N) (random access needs the chain)
    if (o.n > 100000000)
      throw InvalidInput("N", " " + std::to_string(o.n) + ": --types/--polydisperse store the chain (<= 1e8)");
    validate(p);
    s.source = chain_beads(from_radii(realization_radii(*beads, p.N, p.seed, p.realization), o.f0));
    d["beads"] = describe(*beads);
    d["seed"] = o.seed;
    d["realization"] = o.realization;
  } else if (!o.radii.empty()) {
    if (!(o.f0 > 0) || !std::isfinite(o.f0))
      throw InvalidInput("F0",
                         " " + format_number(o.f0) + ": must be finite and > 0 (the sonic vacuum has no linear limit)");
    std::vector<std::string> warnings;
    s.source = chain_beads(from_radii(read_radii_file(o.radii, &warnings), o.f0));
    for (const auto& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    d["radii_file"] = o.radii;
  } else {
    d["R1_m"] = o.r1;
    d["xi"] = o.xi;
    if (!o.config.empty()) {
      s.source = typed_beads(read_configuration_file(o.config), p);
      d["config_file"] = o.config;
    } else {
      const Disorder kind = parse_disorder(o.disorder);
      s.source = random_beads(kind, p);
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
