#pragma once
// The chain of chain_options.hpp (same flags) as a bead source, for tools that walk a chain once
// instead of storing it (localization): a random realization is drawn a piece at a time, so N
// can be far beyond the 1e8 beads of a stored chain with memory independent of N. --config and
// --radii files are read whole (they are O(N) on disk anyway).
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "chain_options.hpp"
#include "granular/model/bead_source.hpp"

namespace granular::tool {

struct StreamedChain {
  std::unique_ptr<BeadSource> source;
  nlohmann::json description;
  double highest_frequency_khz = 0;  ///< bound on every linear frequency (model/plausibility.hpp)
};

inline StreamedChain build_bead_source(const ChainOptions& o) {
  if (o.n < 2 || o.n > 1000000000000) throw InvalidInput("N", " " + std::to_string(o.n) + ": must be in [2, 1e12]");
  ChainOptions stored = o;
  stored.n = 2;  // N checked below, by what the chain is
  ChainRecipe recipe = chain_recipe(stored);
  recipe.N = static_cast<std::size_t>(o.n);
  if (!recipe.streamed() && recipe.drawn() && o.n > 100000000)
    throw InvalidInput("N", " " + std::to_string(o.n) +
                                ": --types/--polydisperse/--quasi/--walls sphere store the chain (<= 1e8)");
  validate(recipe, recipe.largest_walked_size());
  warn(radius_warnings(recipe, radius_options(o)));
  StreamedChain s;
  s.source = recipe.beads(chain_realization(o));
  s.description = describe(recipe, chain_realization(o));
  s.highest_frequency_khz = highest_frequency_bound_khz(recipe);
  return s;
}

}  // namespace granular::tool
