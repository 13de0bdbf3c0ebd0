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
  const ChainParameters p = chain_parameters(o);
  if (o.n < 2 || o.n > 1000000000000) throw InvalidInput("N", " " + std::to_string(o.n) + ": must be in [2, 1e12]");
  StreamedChain s;
  s.description = chain_description(o);
  if (const auto beads = bead_distribution(o)) {  // stored: memory O(N) (random access needs the chain)
    if (o.n > 100000000)
      throw InvalidInput("N", " " + std::to_string(o.n) + ": --types/--polydisperse store the chain (<= 1e8)");
    validate(p);
    s.source = chain_beads(from_radii(realization_radii(*beads, p.N, p.seed, p.realization), o.f0));
  } else if (!o.radii.empty()) {
    if (!(o.f0 > 0) || !std::isfinite(o.f0))
      throw InvalidInput("F0",
                         " " + format_number(o.f0) + ": must be finite and > 0 (the sonic vacuum has no linear limit)");
    s.source = chain_beads(from_radii(read_radii_warning(o.radii), o.f0));
  } else if (!o.config.empty()) {
    s.source = typed_beads(read_configuration_file(o.config), p);
  } else {
    s.source = random_beads(parse_disorder(o.disorder), p);
  }
  s.description["N"] = s.source->size();
  return s;
}

}  // namespace granular::tool
