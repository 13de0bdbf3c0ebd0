#include "granular/io/run_metadata.hpp"

#include <cstdio>
#include <ctime>

#include "granular/blas_library.hpp"
#include "granular/code_identity.hpp"

namespace granular {

RunMetadata::RunMetadata(const std::string& program, const std::string& command, bool quiet)
    : start_(std::chrono::steady_clock::now()), quiet_(quiet) {
  json_["tool"] = program;
  json_["version"] = code_version();
  json_["commit"] = code_commit();  // the version changes with releases, the code with every commit
  json_["blas"] = blas_library();
  json_["command"] = command;
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  json_["started_utc"] = stamp;
}

void RunMetadata::write(const std::string& path, const std::vector<PendingOutput*>& outputs) {
  write_json(path);
  for (PendingOutput* f : outputs) f->commit();
  report(path);
}

void RunMetadata::write(const std::string& path, const std::vector<std::unique_ptr<AtomicFile>>& outputs) {
  write_json(path);
  for (const auto& f : outputs) f->commit();
  report(path);
}

void RunMetadata::write(const std::string& path) {
  write_json(path);
  report(path);
}

void RunMetadata::write_json(const std::string& path) {
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  json_["wall_time_s"] = seconds_;
  write_file_atomically(path, json_.dump(2) + "\n");
}

void RunMetadata::report(const std::string& path) const {
  if (quiet_) return;
  std::string files;
  for (const char* key : {"output", "vectors"})
    if (json_.contains(key) && json_.at(key).is_string()) files += json_.at(key).get<std::string>() + ", ";
  char line[64];
  std::snprintf(line, sizeof line, " in %.3g s", seconds_);
  std::fprintf(stderr, "%s: wrote %s%s%s%s\n", json_.at("tool").get<std::string>().c_str(), files.c_str(), path.c_str(),
               line, notes_.c_str());
}

}  // namespace granular
