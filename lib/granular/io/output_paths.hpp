#pragma once
// Where a run's outputs go. Every output is named from one PREFIX (PREFIX.csv, PREFIX.json,
// PREFIX-<more>.csv, …) and checked before the run (a writable folder, no two outputs on one
// path), so that hours of computing never end in a file that cannot be written.
#include <string>
#include <vector>

namespace granular {

/// The prefix an output name stands for: a trailing ".csv" is dropped, so "run" and "run.csv"
/// both name the outputs run.csv, run.json (and run-*.csv, …). Anything else is kept as it is.
std::string output_prefix(const std::string& output);

/// Throws IoError for an output whose folder cannot be written, InvalidInput when two of `paths`
/// (empty ones skipped) are the same file; the message starts with `names` (what the user calls
/// these outputs, e.g. the options that name them).
void check_outputs(const std::vector<std::string>& paths, const std::string& names);

/// The outputs of a run that writes one table: PREFIX.csv and its JSON, PREFIX.json.
struct TableOutputs {
  std::string csv, json;
};

/// PREFIX.csv and PREFIX.json of `prefix`, each checked writable (atomic_file.hpp: check_writable)
/// before the run.
TableOutputs table_outputs(const std::string& prefix);

}  // namespace granular
