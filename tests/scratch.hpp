#pragma once
// A folder of its own under the build tree for a test's files.
#include <filesystem>
#include <string>

namespace granular::testing {

/// The path of `name` in GRANULAR_BINARY_DIR/`folder`, the folder created if needed.
inline std::string scratch_path(const std::string& folder, const std::string& name) {
  const auto dir = std::filesystem::path(GRANULAR_BINARY_DIR) / folder;
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

}  // namespace granular::testing
