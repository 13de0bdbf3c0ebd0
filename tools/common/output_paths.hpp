#pragma once
// Every output of a run is checked before the run (writable folder, no two outputs on one path)
// and written only after it.
#include <filesystem>
#include <string>
#include <vector>

#include "granular/error.hpp"
#include "granular/io/atomic_file.hpp"

namespace granular::tool {

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
