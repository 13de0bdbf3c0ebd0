#pragma once
// The JSON that sits beside every output of a run: enough to reproduce it — the program, the
// toolkit's version, the command line, the start time (UTC) and the wall time [s], and whatever
// the run adds (its parameters, from the library's describe functions). Written before the outputs
// are committed, so a crash can leave metadata without its CSV, never a CSV without its metadata.
//
//   RunMetadata meta("spectrum", shell_command(words));
//   meta.merge(describe_spectrum(...));
//   AtomicFile csv("run.csv");  ... write ...
//   meta.write("run.json", {&csv});  // JSON, then the CSV, then one line on stderr
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "granular/io/atomic_file.hpp"
#include "granular/io/pending_output.hpp"

namespace granular {

class RunMetadata {
 public:
  /// `program` names the run ("tool"), `command` is its command line as the user typed it
  /// (io/shell_quote.hpp); `quiet`: write no final line. The clock starts here.
  RunMetadata(const std::string& program, const std::string& command, bool quiet = false);

  nlohmann::json& operator[](const char* key) { return json_[key]; }
  /// Adds the entries of `entries` (a library describe_* result), replacing those of the same key.
  void merge(const nlohmann::json& entries) { json_.update(entries); }
  /// A remark the final line must carry (e.g. realizations left out), never only the JSON.
  void note(const std::string& text) { notes_ += "; " + text; }
  /// The command line given to the constructor.
  std::string command() const { return json_.at("command").get<std::string>(); }

  /// Writes the JSON at `path` (with the wall time, atomically), then commits `outputs` (already
  /// written under their temporary names), then ends the run with the final line.
  void write(const std::string& path, const std::vector<PendingOutput*>& outputs);
  void write(const std::string& path, const std::vector<std::unique_ptr<AtomicFile>>& outputs);
  /// The same with no outputs to commit (the caller commits its own after this).
  void write(const std::string& path);

 private:
  void write_json(const std::string& path);
  /// Unless quiet: one line on stderr, "<program>: wrote <output>, <vectors>, <path> in <t> s<notes>".
  void report(const std::string& path) const;

  nlohmann::json json_;
  std::chrono::steady_clock::time_point start_;
  bool quiet_ = false;
  double seconds_ = 0;
  std::string notes_;
};

}  // namespace granular
