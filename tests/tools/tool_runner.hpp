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

#include "granular/parameter_names.hpp"

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

/// What `tool --help` prints.
inline std::string tool_help(const std::string& tool) {
  std::string command = "'";  // (append: GCC 12 warns falsely of overlap in a chain of +)
  command.append(tool_path(tool)).append("' --help");
  std::string out;
  if (FILE* p = ::popen(command.c_str(), "r")) {
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, p)) > 0;) out.append(buffer, n);
    ::pclose(p);
  }
  return out;
}

/// A tool's flag for the library's parameter `parameter` (its front-end word, '_' as '-').
inline std::string flag_for(const std::string& parameter) {
  std::string flag = "--";
  flag.append(front_end_word(parameter));
  for (std::size_t i = 2; i < flag.size(); ++i)
    if (flag[i] == '_') flag[i] = '-';
  return flag;
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
