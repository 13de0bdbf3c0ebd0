#pragma once
// Runs a tool from the build tree as a user would, capturing exit code and stderr.
#include <sys/wait.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace granular::testing {

struct ToolResult {
  int exit_code = -1;
  std::string err;
};

inline std::string tool_path(const std::string& name) { return std::string(GRANULAR_BINARY_DIR) + "/" + name; }

/// Runs `tool args` with stderr captured (stdout discarded), in folder `dir` if one is given
/// (so relative output paths land there).
inline ToolResult run_tool_in(const std::string& dir, const std::string& tool, const std::string& args) {
  const std::string err_file = std::filesystem::temp_directory_path() / ("granular-err-" + std::to_string(::getpid()));
  const std::string cd = dir.empty() ? "" : "cd '" + dir + "' && ";
  const std::string command = cd + "'" + tool_path(tool) + "' " + args + " >/dev/null 2>" + err_file;
  const int status = std::system(command.c_str());
  ToolResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err_file);
  std::stringstream text;
  text << in.rdbuf();
  r.err = text.str();
  std::filesystem::remove(err_file);
  return r;
}

inline ToolResult run_tool(const std::string& tool, const std::string& args) { return run_tool_in("", tool, args); }

/// Whether `args` read the chain from a file (--config or --radii), which then sets N.
inline bool reads_chain_file(const std::string& args) {
  return args.find("--config") != std::string::npos || args.find("--radii") != std::string::npos;
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A fresh, empty folder for one test's outputs.
inline std::string scratch_folder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("granular-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace granular::testing
