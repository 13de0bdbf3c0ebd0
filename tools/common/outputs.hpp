#pragma once
// A tool's outputs: --output PREFIX, read by the library's rule (io/output_paths.hpp: a trailing
// .csv is dropped); the claim of the prefix (io/output_claim.hpp: PREFIX.lock, rank 0 for all
// ranks), where a run that checkpoints refuses to start afresh over the checkpoint of an
// interrupted run unless told to (--fresh) — a refusal is bad input (exit 2): the user asked for
// an output another run owns; and the JSON beside every CSV (io/run_metadata.hpp), made from the
// tool's argv: the command line as typed, shell-quoted; --quiet silences the final line.
#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "granular/ensemble/resumed_checkpoint.hpp"
#include "granular/error.hpp"
#include "granular/io/output_claim.hpp"
#include "granular/io/output_paths.hpp"
#include "granular/io/run_metadata.hpp"
#include "granular/io/shell_quote.hpp"

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

/// Claims `prefix`; with `checkpoints`, the checkpoint PREFIX.checkpoint[.<case>] an interrupted
/// run left is settled as the choices say (settle_checkpoints: refused, or with --fresh removed).
inline OutputClaim claim_output(const std::string& prefix, const std::string& command,
                                std::optional<RunOptions> checkpoints = std::nullopt) {
  return OutputClaim(prefix, command, [&] {
    if (checkpoints) settle_checkpoints(*checkpoints, prefix + ".checkpoint");
  });
}

struct Metadata : RunMetadata {
  Metadata(const std::string& tool, int argc, char** argv)
      : RunMetadata(tool, shell_command(std::vector<std::string>(argv, argv + argc)),
                    std::find(argv, argv + argc, std::string_view("--quiet")) != argv + argc) {}
};

}  // namespace granular::tool
