#pragma once
// `--N auto` for long runs (docs/physics.md, "Chain length for long times"): N sized from --T so
// that no wave from the kicked centre bead reaches a wall (chain_length_rule.hpp), the chain drawn
// outward from that bead (centred_configuration.hpp) so that a longer N only adds beads the wave
// never reaches. Given a number, --N keeps its meaning and the draw from the left wall.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "granular/study/chain_length_rule.hpp"
#include "granular/study/transport_study.hpp"

namespace granular::tool {

/// Lets the tool's --N option take 'auto' (then `auto_n` is set and N reads as 3 until sized).
inline void add_auto_length(CLI::App& app, bool& auto_n) {
  CLI::Option* n = app.get_option("--N");
  n->description(n->get_description() +
                 "; 'auto': sized from --T so that no wave reaches a wall (docs/physics.md, 'Chain length for long "
                 "times'), the kick at the centre of a chain drawn outward from it; rule and N in the JSON");
  n->transform(CLI::Validator(
      [&auto_n](std::string& text) -> std::string {
        if (text == "auto") {
          auto_n = true;
          text = "3";
        }
        return {};
      },
      ""));
  n->type_name("INT|auto");
}

/// --N auto kicks the centre bead: only --site 0 goes with it.
inline void require_centre_kick(long long site) {
  if (site != 0) throw InvalidInput("--site " + std::to_string(site) + ": --N auto kicks the centre bead (--site 0)");
}

/// exponents: the rules of its cases (sized by exponent_cases) when `auto_n`, else null.
inline nlohmann::json length_rules(const std::vector<TransportCase>& cases, bool auto_n, long long site) {
  if (!auto_n) return nullptr;
  require_centre_kick(site);
  nlohmann::json rules = nlohmann::json::array();
  for (const TransportCase& c : cases) rules.push_back(to_json(automatic_chain_length(c)));
  return rules;
}

}  // namespace granular::tool
