#pragma once
// Every output of a run is checked before the run (writable folder, no two outputs on one path)
// and written only after it.
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "granular/io/atomic_file.hpp"

namespace granular::tool {

/// The one --output rule of every tool: the value is a PREFIX, and a trailing ".csv" is dropped,
/// so "--output run" and "--output run.csv" both write run.csv, run.json (and run-*.csv, ...).
inline std::string output_prefix(const std::string& output) {
  const std::string ext = ".csv";
  if (output.size() > ext.size() && output.compare(output.size() - ext.size(), ext.size(), ext) == 0)
    return output.substr(0, output.size() - ext.size());
  return output;
}

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

/// Throws IoError for an unwritable folder, InvalidInput naming `options` when two of `paths`
/// (empty ones skipped) are the same file.
inline void check_outputs(const std::vector<std::string>& paths, const std::string& options) {
  std::vector<std::filesystem::path> seen;
  for (const std::string& p : paths) {
    if (p.empty()) continue;
    const auto normal = std::filesystem::absolute(p).lexically_normal();
    for (const auto& s : seen)
      if (s == normal) throw InvalidInput(options + ": two outputs would both be " + p);
    seen.push_back(normal);
  }
  for (const std::string& p : paths)
    if (!p.empty()) check_writable(p);
}

}  // namespace granular::tool
