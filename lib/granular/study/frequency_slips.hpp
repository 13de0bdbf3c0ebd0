#pragma once
// Hz typed as kHz, for every frequency a front end takes: one rule (model/plausibility.hpp,
// frequency_warning: above every linear frequency of the chain) applied to each frequency of a
// breather branch, a mode kick and a mode selection, so the tools and Python warn alike. Each
// warning names the parameter as `told` says it (a tool: its flag; Python: its keyword).
#include <functional>
#include <string>
#include <vector>

#include "granular/case/mode_kick.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/chain_recipe.hpp"
#include "granular/orbits/breather_branch.hpp"
#include "granular/study/ipr_map.hpp"
#include "granular/study/transport_study.hpp"

namespace granular {

using Told = std::function<std::string(const std::string&)>;

/// The breather seed and ends above every frequency of the branch's chain: `near_khz`,
/// `start_khz`, `target_khz` (none at F0 = 0, where no bound is known).
std::vector<std::string> frequency_slips(const BreatherBranchConfig& c, const Told& told);

/// A mode kick's `near_khz` above every frequency of `chain`.
std::vector<std::string> frequency_slips(const ModeKick& kick, const ChainRecipe& chain, const Told& told);

/// The first of `cases` (an exponent table's chains) whose mode kick's `near_khz` is above every
/// frequency of its chain: one warning for the table.
std::vector<std::string> frequency_slips(const std::vector<TransportCase>& cases, const Told& told);

/// A selection's `near` or the low end of its `window` above every frequency of `chain`.
std::vector<std::string> frequency_slips(const ModeSelection& s, const ChainRecipe& chain, const Told& told);

/// An IPR map's selection (`near`, `window`) above every frequency of its chains (those of its
/// smallest size ratio: the lightest beads).
std::vector<std::string> frequency_slips(const IprMapConfig& c, const Told& told);

}  // namespace granular
