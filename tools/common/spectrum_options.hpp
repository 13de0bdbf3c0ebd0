#pragma once
// The options that choose modes (spectrum, ipr-map): --near/--count or --window, the library's
// choices (linear/mode_selection_choices.hpp) with each --help line after a word of the tool's.
#include <optional>
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

/// The options as typed, --window as its text: the command-line form selection_options_test
/// checks (the tools bind ModeSelectionChoices, reading --window as it is parsed).
struct SelectionOptions {
  std::optional<double> near;
  std::optional<long> count;
  std::optional<std::string> window;
};

/// The library's rule (choose_modes) once --window's text is read by the library's form.
inline ModeSelection parse_selection(const SelectionOptions& o) {
  ModeSelectionChoices choices{.near = o.near, .count = o.count};
  if (o.window) parameter(mode_selection_parameters(), "window").text->read(choices, *o.window);
  return choose_modes(choices);
}

}  // namespace granular::tool
