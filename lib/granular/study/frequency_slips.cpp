#include "granular/study/frequency_slips.hpp"

#include <algorithm>
#include <cmath>

#include "granular/model/plausibility.hpp"

namespace granular {

std::vector<std::string> frequency_slips(const BreatherBranchConfig& c, const Told& told) {
  if (std::isnan(c.near_khz) && std::isnan(c.start_khz) && std::isnan(c.target_khz)) return {};  // none given
  const double top = highest_frequency_bound_khz(c.chain);
  std::vector<std::string> slips;
  for (const auto& [name, khz] :
       {std::pair{"near_khz", c.near_khz}, {"start_khz", c.start_khz}, {"target_khz", c.target_khz}})
    if (std::string w = frequency_warning(told(name), khz, top); !w.empty()) slips.push_back(std::move(w));
  return slips;
}

std::vector<std::string> frequency_slips(const ModeKick& kick, const ChainRecipe& chain, const Told& told) {
  if (!kick.near_khz) return {};  // no frequency: the chain's bound is not needed (nor its radii valid yet)
  std::string w = frequency_warning(told("near_khz"), *kick.near_khz, highest_frequency_bound_khz(chain));
  return w.empty() ? std::vector<std::string>{} : std::vector<std::string>{std::move(w)};
}

std::vector<std::string> frequency_slips(const std::vector<TransportCase>& cases, const Told& told) {
  for (const TransportCase& c : cases)
    if (auto slips = frequency_slips(c.mode, c.chain, told); !slips.empty()) return slips;
  return {};
}

std::vector<std::string> frequency_slips(const ModeSelection& s, const ChainRecipe& chain, const Told& told) {
  if (s.kind == ModeSelection::Kind::all) return {};
  const bool near = s.kind == ModeSelection::Kind::nearest;
  std::string w = frequency_warning(told(near ? "near" : "window"), near ? s.near_khz : s.lo_khz,
                                    highest_frequency_bound_khz(chain));
  return w.empty() ? std::vector<std::string>{} : std::vector<std::string>{std::move(w)};
}

std::vector<std::string> frequency_slips(const IprMapConfig& c, const Told& told) {
  ChainRecipe highest = c.chain;
  if (auto* draw = highest.as<TwoTypeDraw>(); draw && !c.xi_values.empty())
    draw->xi = *std::min_element(c.xi_values.begin(), c.xi_values.end());
  return frequency_slips(c.selection, highest, told);
}

}  // namespace granular
