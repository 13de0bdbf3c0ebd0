#pragma once
// Tools run as background processes, to be signalled mid-run (kill loops, Ctrl-C, two writers).
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>

#include "tool_runner.hpp"

namespace granular::testing {

/// Starts `command` (a shell command line; it should `exec` the tool so that the pid returned is
/// the tool's own) and returns its pid.
inline pid_t spawn(const std::string& command) {
  const pid_t child = ::fork();
  if (child == 0) {
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return child;
}

struct Ended {
  bool signalled = false;
  int code = -1;  ///< exit code, or the signal number when signalled
};

inline Ended wait_for(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) return {true, WTERMSIG(status)};
  return {false, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

/// Whether `pid` has ended (without reaping it).
inline bool ended(pid_t pid) {
  siginfo_t info{};
  info.si_pid = 0;
  return ::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid;
}

/// Polls `condition` every 5 ms for up to `seconds`; whether it came true.
inline bool eventually(const std::function<bool()>& condition, double seconds = 60) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return condition();
}

/// Runs a command line exactly as printed (by a tool, for the user to paste), in folder `dir`,
/// capturing stderr.
inline ToolResult run_printed(const std::string& dir, const std::string& command) {
  const std::string err_file = dir + "/printed-command.err";
  const int status = std::system(("cd '" + dir + "' && " + command + " >/dev/null 2>" + err_file).c_str());
  ToolResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = read_file(err_file);
  std::filesystem::remove(err_file);
  return r;
}

/// Record lines in a checkpoint file (all lines but the header).
inline long checkpoint_records(const std::string& path) {
  if (!std::filesystem::exists(path)) return 0;
  const std::string text = read_file(path);
  return std::max(0L, static_cast<long>(std::count(text.begin(), text.end(), '\n')) - 1);
}

}  // namespace granular::testing
