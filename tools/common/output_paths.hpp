#pragma once
// --output PREFIX, read by the library's rule (io/output_paths.hpp: a trailing .csv is dropped).
#include <string>

#include <CLI/CLI.hpp>

#include "granular/io/output_paths.hpp"

namespace granular::tool {

/// Adds --output PREFIX to `app`, read through output_prefix (so `output` is always the prefix);
/// `more` names the tool's other files under PREFIX for --help.
inline CLI::Option* add_output_option(CLI::App& app, std::string& output, const std::string& more = "") {
  return app
      .add_option("--output", output,
                  "prefix: writes PREFIX.csv and PREFIX.json" + more +
                      " (a trailing .csv is dropped: --output run and --output run.csv both write run.csv)")
      ->transform([](const std::string& value) { return output_prefix(value); }, "", "")
      ->capture_default_str();
}

}  // namespace granular::tool
