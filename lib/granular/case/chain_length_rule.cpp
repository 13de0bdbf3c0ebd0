#include "granular/case/chain_length_rule.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "granular/case/time_step_rule.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/number_format.hpp"

namespace granular {

ChainLength automatic_chain_length(const TransportCase& c) {
  if (c.kick == Kick::mode && !(c.mode.energy > 0))  // α bounds a mode's energy only for a known N
    throw InvalidInput("energy", ": a mode kick on the automatic N needs its energy, not its amplitude");
  TransportCase probe = c;  // ω_max depends on the chain and the kick, not on the scheme
  probe.dynamics.integration.integrator = saba2c();
  probe.chain.N = 3;
  if (auto* draw = probe.chain.as<TwoTypeDraw>()) draw->centred = false;
  probe.site = 0;  // the centre
  ChainLength length;
  length.omega_max = time_step_limit(probe).omega_max;
  length.max_group_velocity = length.omega_max / 2;
  length.reach = length.max_group_velocity * c.dynamics.integration.duration;
  const double half = std::ceil(length.safety * length.reach) + static_cast<double>(length.pad);
  if (!(half < 5e7))
    throw InvalidInput("N", ": the automatic chain length for T = " + std::to_string(c.dynamics.integration.duration) +
                                " s passes 1e8 beads");
  length.n = 2 * static_cast<std::size_t>(half) + 1;
  return length;
}

ChainLength size_for_long_times(TransportCase& c) {
  const ChainLength length = automatic_chain_length(c);
  c.chain.N = length.n;
  c.site = 0;  // the centre
  auto* draw = c.chain.as<TwoTypeDraw>();
  if (!draw)
    throw InvalidInput("N", ": a chain drawn from its centre (the automatic N) has two bead types, not a bead source");
  draw->centred = true;
  return length;
}

std::string duration_warning(const TransportCase& c, double omega_max, const std::string& option) {
  const std::size_t n = c.chain.size();
  if (c.site > n) return "";  // validate() names it
  const std::size_t site = kicked_bead(c);
  const double wall = static_cast<double>(std::min(site + 1, n - site));
  const double speed = omega_max / 2;
  if (!(speed * c.dynamics.integration.duration > 10 * wall)) return "";
  return option + " " + format_number(c.dynamics.integration.duration) +
         ": waves from the kick reach a wall after about " + format_number(std::round(wall / speed * 1e6) / 1e6) +
         " s and cross the " + std::to_string(n) +
         "-bead chain many times by T; T is in seconds (milliseconds typed as seconds?)";
}

void require_centre_kick(long long site) {
  if (site != 0) throw InvalidInput("site", " " + std::to_string(site) + ": `N` auto kicks the centre bead (`site` 0)");
}

nlohmann::json length_rules(const std::vector<TransportCase>& cases, bool automatic, long long site) {
  if (!automatic) return nullptr;
  require_centre_kick(site);
  nlohmann::json rules = nlohmann::json::array();
  for (const TransportCase& c : cases) rules.push_back(to_json(automatic_chain_length(c)));
  return rules;
}

const ParameterTable<ChainChoices>& long_run_chain_parameters() {
  static const ParameterTable<ChainChoices> table = [] {
    ParameterTable<ChainChoices> t = chain_parameters();
    const auto read = [](ChainChoices& o, const std::string& text) {
      o.auto_n = text == "auto";
      if (o.auto_n) {
        o.n = 3;  // until sized
        return;
      }
      try {  // one integer; 1e4 reads as 10000, as every integer option does
        if (const auto n = parse_integer_list(integer_digits(text, "N"), "N"); n.size() == 1) {
          o.n = n.front();
          return;
        }
      } catch (const InvalidInput&) {
      }
      throw InvalidInput("N", " " + text + ": an integer or 'auto'");
    };
    const auto write = [](const ChainChoices& o) { return o.auto_n ? std::string("auto") : std::to_string(o.n); };
    for (Parameter<ChainChoices>& p : t)
      if (p.name == "N") {
        p.text = TextForm<ChainChoices>{read, write};
        p.help +=
            "; 'auto': sized from `duration` so that no wave reaches a wall (docs/physics.md, 'Chain length "
            "for long times'), the kick at the centre of a chain drawn outward from it; rule and N in the JSON";
      }
    return t;
  }();
  return table;
}

nlohmann::json to_json(const ChainLength& length) {
  return {{"rule",
           "N = 2*ceil(safety*v*T) + 1 + 2*pad, the kick at the centre bead; v = omega_max/2 [beads/s] bounds "
           "the fastest group velocity (omega_max: the time-step rule's bound of the highest angular frequency "
           "at the stiffest bond the kick energy allows); the chain drawn outward from the centre bead"},
          {"omega_max_rad_s", length.omega_max},
          {"max_group_velocity_beads_per_s", length.max_group_velocity},
          {"reach_beads", length.reach},
          {"safety_factor", length.safety},
          {"pad_beads", length.pad},
          {"N", length.n}};
}

}  // namespace granular
