#include "granular/model/selected_chain.hpp"

#include <utility>

namespace granular {

SelectedChain select_chain(ChainRecipe recipe, std::uint64_t realization, const RadiusNames& names) {
  validate(recipe);
  SelectedChain s;
  s.warnings = radius_warnings(recipe, names);
  s.chain = recipe.chain(realization);
  s.description = describe(recipe, realization);
  s.realization = realization;
  s.recipe = std::move(recipe);
  return s;
}

StreamedChain stream_chain(const ChainRecipe& recipe, std::uint64_t realization, const RadiusNames& names) {
  validate(recipe, recipe.largest_walked_size());
  StreamedChain s;
  s.warnings = radius_warnings(recipe, names);
  s.beads = recipe.beads(realization);
  s.description = describe(recipe, realization);
  s.highest_frequency_khz = highest_frequency_bound_khz(recipe);
  return s;
}

}  // namespace granular
