#pragma once
// The JSON that sits beside every CSV: enough to reproduce the run.
#include <chrono>
#include <ctime>
#include <string>

#include <nlohmann/json.hpp>

#include "granular/io/atomic_file.hpp"

namespace granular::tool {

class Metadata {
 public:
  Metadata(const std::string& tool, int argc, char** argv) : start_(std::chrono::steady_clock::now()) {
    std::string command;
    for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
    json_["tool"] = tool;
    json_["version"] = GRANULAR_VERSION;
    json_["command"] = command;
    const std::time_t now = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    json_["started_utc"] = stamp;
  }
  nlohmann::json& operator[](const char* key) { return json_[key]; }
  /// Adds the wall time and writes the file atomically.
  void write(const std::string& path) {
    json_["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    write_file_atomically(path, json_.dump(2) + "\n");
  }

 private:
  nlohmann::json json_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace granular::tool
