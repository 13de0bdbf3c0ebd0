#pragma once
// `--N auto` for long runs (docs/physics.md, "Chain length for long times"): N sized from --T so
// that no wave from the kicked centre bead reaches a wall (study/chain_length_rule.hpp), the chain drawn
// outward from that bead (centred_configuration.hpp) so that a longer N only adds beads the wave
// never reaches. Given a number, --N keeps its meaning and the draw from the left wall.
#include <string>

#include <CLI/CLI.hpp>

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

}  // namespace granular::tool
