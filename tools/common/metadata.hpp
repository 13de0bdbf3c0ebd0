#pragma once
// The JSON that sits beside every CSV: enough to reproduce the run.
#include <chrono>
#include <cstdio>
#include <string_view>
#include <ctime>
#include <string>

#include <nlohmann/json.hpp>

#include "granular/io/atomic_file.hpp"

namespace granular::tool {

class Metadata {
 public:
  Metadata(const std::string& tool, int argc, char** argv) : start_(std::chrono::steady_clock::now()) {
    std::string command;
    for (int i = 0; i < argc; ++i) {
      command += (i ? " " : "") + std::string(argv[i]);
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
  /// Adds the wall time, writes the file atomically, and (unless --quiet) ends the run with one
  /// line on stderr saying what was written where and how long it took.
  void write(const std::string& path) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    json_["wall_time_s"] = seconds;
    write_file_atomically(path, json_.dump(2) + "\n");
    if (quiet_) return;
    std::string files;
    for (const char* key : {"output", "vectors"})
      if (json_.contains(key) && json_[key].is_string()) files += json_[key].get<std::string>() + ", ";
    char line[64];
    std::snprintf(line, sizeof line, " in %.3g s", seconds);
    std::fprintf(stderr, "%s: wrote %s%s%s\n", json_["tool"].get<std::string>().c_str(), files.c_str(), path.c_str(), line);
  }

 private:
  nlohmann::json json_;
  std::chrono::steady_clock::time_point start_;
  bool quiet_ = false;
};

}  // namespace granular::tool
