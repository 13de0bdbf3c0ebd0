#pragma once
// Flags declared as a table: a row names the flag, the option field it sets and its help; add_flags
// registers the rows of a table on a tool.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>

namespace granular::tool {

template <class Options>
struct Flag {
  std::string name;
  std::variant<double Options::*, long long Options::*, long Options::*, std::string Options::*,
               std::optional<double> Options::*>
      field;
  std::string help;
  bool shows_default = true;  ///< --help shows the default value
};

/// Registers every row of `flags` on `app`, bound to its field of `o`.
template <class Options>
void add_flags(CLI::App& app, Options& o, const std::vector<Flag<Options>>& flags) {
  for (const Flag<Options>& f : flags)
    std::visit(
        [&](auto field) {
          CLI::Option* option = app.add_option(f.name, o.*field, f.help);
          if (f.shows_default) option->capture_default_str();
        },
        f.field);
}

}  // namespace granular::tool
