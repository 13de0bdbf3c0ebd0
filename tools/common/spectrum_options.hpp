#pragma once
// The options that choose modes (spectrum, ipr-map): --near/--count or --window, the library's
// choices (linear/mode_selection_choices.hpp) with each --help line after a word of the tool's.
#include <string>

#include <CLI/CLI.hpp>

#include "granular/linear/mode_selection_choices.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// `what` ("partial spectra: " or "") before each --help line.
inline void add_selection_options(CLI::App& app, ModeSelectionChoices& o, const std::string& what) {
  for (const auto& [name, option] : add_parameters(app, o, mode_selection_parameters()))
    option->description(what + option->get_description());
}

}  // namespace granular::tool
