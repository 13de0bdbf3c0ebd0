#pragma once
// A recipe's realization made ready for a run, the same way for every front end: the recipe
// checked, a warning for each implausible radius in the caller's names (plausibility.hpp), the
// chain built (stored, or streamed a piece at a time) and described for the run's JSON.
//
//   SelectedChain s = select_chain(recipe, 3, {"R1", "beads", "radii"});
//   for (const auto& w : s.warnings) show(w);  // the caller's way: stderr, a Python warning
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "granular/model/bead_source.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/chain_recipe.hpp"
#include "granular/model/plausibility.hpp"

namespace granular {

struct SelectedChain {
  ChainRecipe recipe;  ///< what the chain is a realization of
  std::uint64_t realization = 0;
  Chain chain;                        ///< recipe.chain(realization)
  nlohmann::json description;         ///< describe(recipe, realization): the JSON's "chain" entry
  std::vector<std::string> warnings;  ///< implausible radii, for the caller to show
};

/// Realization `realization` of `recipe`, validated (InvalidInput naming the field) and stored.
SelectedChain select_chain(ChainRecipe recipe, std::uint64_t realization, const RadiusNames& names);

struct StreamedChain {
  std::unique_ptr<BeadSource> beads;  ///< recipe.beads(realization)
  nlohmann::json description;         ///< as SelectedChain's
  double highest_frequency_khz = 0;   ///< highest_frequency_bound_khz: above it no mode of the chain
  std::vector<std::string> warnings;  ///< implausible radii
};

/// The same chain walked once instead of stored: N up to recipe.largest_walked_size() (a random
/// two-type draw is streamed, so its memory does not grow with N).
StreamedChain stream_chain(const ChainRecipe& recipe, std::uint64_t realization, const RadiusNames& names);

}  // namespace granular
