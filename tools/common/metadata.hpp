#pragma once
// The JSON that sits beside every CSV: enough to reproduce the run.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <initializer_list>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "granular/io/atomic_file.hpp"

namespace granular::tool {

class Metadata {
 public:
  Metadata(const std::string& tool, int argc, char** argv) : start_(std::chrono::steady_clock::now()) {
    std::string command;
    for (int i = 0; i < argc; ++i) {
      command += (i ? " " : "") + shell_quote(argv[i]);
      if (std::string_view(argv[i]) == "--quiet") quiet_ = true;
    }
    json_["tool"] = tool;
    json_["version"] = GRANULAR_VERSION;
    json_["command"] = command;
    const std::time_t now = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    json_["started_utc"] = stamp;
  }
  nlohmann::json& operator[](const char* key) { return json_[key]; }
  /// Adds the entries of `entries` (a library describe_* result), replacing those of the same key.
  void merge(const nlohmann::json& entries) { json_.update(entries); }
  /// A remark the final line must carry (e.g. realizations left out), never only the JSON.
  void note(const std::string& text) { notes_ += "; " + text; }
  /// The command line as typed, quoted for a POSIX shell: paste it back and it runs.
  std::string command() const { return json_.at("command").get<std::string>(); }

  /// Writes the JSON, then commits `outputs` (already written under temporary names): a crash
  /// can leave metadata without its CSV, never a CSV without its metadata. Then the final line.
  void write(const std::string& path, std::initializer_list<AtomicFile*> outputs) {
    write_json(path);
    for (AtomicFile* f : outputs) f->commit();
    report(path);
  }
  /// Adds the wall time, writes the file atomically, and (unless --quiet) ends the run with one
  /// line on stderr saying what was written where and how long it took.
  void write(const std::string& path) {
    write_json(path);
    report(path);
  }

  static std::string shell_quote(const std::string& word) {
    if (!word.empty() &&
        word.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_@%+=:,./-") ==
            std::string::npos)
      return word;
    std::string quoted = "'";
    for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
  }

 private:
  void write_json(const std::string& path) {
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    json_["wall_time_s"] = seconds_;
    write_file_atomically(path, json_.dump(2) + "\n");
  }

  void report(const std::string& path) const {
    if (quiet_) return;
    const double seconds = seconds_;
    std::string files;
    for (const char* key : {"output", "vectors"})
      if (json_.contains(key) && json_.at(key).is_string()) files += json_.at(key).get<std::string>() + ", ";
    char line[64];
    std::snprintf(line, sizeof line, " in %.3g s", seconds);
    std::fprintf(stderr, "%s: wrote %s%s%s%s\n", json_.at("tool").get<std::string>().c_str(), files.c_str(),
                 path.c_str(), line, notes_.c_str());
  }

  nlohmann::json json_;
  std::chrono::steady_clock::time_point start_;
  bool quiet_ = false;
  double seconds_ = 0;
  std::string notes_;
};

}  // namespace granular::tool
