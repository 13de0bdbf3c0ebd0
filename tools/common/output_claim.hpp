#pragma once
// What a tool does before it touches any file of an output prefix: it takes PREFIX.lock (one
// writer per output: a second run on the prefix is refused, naming the process that holds it;
// the kernel drops the lock of a killed run, so a resume is never blocked), and, for a run that
// checkpoints, refuses to start afresh over the checkpoint of an interrupted run unless told to
// (--fresh). Under mpirun rank 0 alone claims the prefix; every rank learns whether it could.
// A refusal is bad input (exit 2): the user asked for an output another run owns.
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include "granular/error.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/output_lock.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "output_paths.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// The checkpoint files a run on `prefix` writes, and only those: PREFIX.checkpoint (a single
/// ensemble) or PREFIX.checkpoint.<case> (a study's cases), each with .rank<k> per further MPI
/// rank; with `temporaries`, also the .tmp.<pid> a killed run left while writing one. A file the
/// user named alike (PREFIX.checkpoint.bak) is not one of them.
inline std::vector<std::string> checkpoint_files(const std::string& prefix, bool temporaries = false) {
  namespace fs = std::filesystem;
  fs::path folder = fs::path(prefix).parent_path();
  const std::string stem = fs::path(prefix).filename().string() + ".checkpoint";
  const auto ours = [&](const std::string& name) {
    if (name.compare(0, stem.size(), stem) != 0) return false;
    std::size_t at = stem.size();
    const auto skip = [&](const std::string& tag) {  // tag followed by digits up to the next '.'
      const std::size_t end = std::min(name.find('.', at + tag.size()), name.size());
      if (name.compare(at, tag.size(), tag) != 0 || end == at + tag.size() ||
          name.find_first_not_of("0123456789", at + tag.size()) < end)
        return false;
      at = end;
      return true;
    };
    skip(".");
    skip(".rank");
    if (temporaries) skip(".tmp.");
    return at == name.size();
  };
  std::vector<std::string> found;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder.empty() ? fs::path(".") : folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (ours(name)) found.push_back((folder / name).string());
  }
  std::sort(found.begin(), found.end());
  return found;
}

struct CheckpointPolicy {
  bool resume = false;  ///< continue from the checkpoint
  bool fresh = false;   ///< discard it and start again
};

class OutputClaim {
 public:
  /// Claims `prefix` for this run (`command` goes into the lock file, for whoever is refused).
  /// With `checkpoints`: a run neither resuming nor fresh is refused when a checkpoint is there;
  /// a fresh one removes it. Throws InvalidInput / IoError on rank 0, QuietExit on the others.
  OutputClaim(const std::string& prefix, const std::string& command,
              std::optional<CheckpointPolicy> checkpoints = std::nullopt) {
    const MpiContext& mpi = MpiContext::instance();
    std::exception_ptr failure;
    bool refused = false;
    if (mpi.root()) try {
        check_writable(prefix + ".lock");  // the folder's problem in the words of every output
        lock_.emplace(prefix, command);
        if (checkpoints) claim_checkpoints(prefix, *checkpoints);
      } catch (const InvalidInput&) {
        failure = std::current_exception();
        refused = true;
      } catch (...) {
        failure = std::current_exception();
      }
    const bool ok = mpi.all(!failure);
    if (ok) return;
    const bool was_refused = !mpi.all(!refused);  // the others exit with rank 0's code
    lock_.reset();
    if (failure) std::rethrow_exception(failure);
    throw QuietExit{was_refused ? ExitCode::bad_input : ExitCode::io_failure};
  }

 private:
  static void claim_checkpoints(const std::string& prefix, const CheckpointPolicy& p) {
    if (p.resume && p.fresh) throw InvalidInput("fresh", ": not with --resume (continue, or start again: one of them)");
    if (p.resume) return;
    const auto files = checkpoint_files(prefix);
    if (files.empty()) return;
    if (!p.fresh)
      throw InvalidInput("output", " '" + prefix + "': " + files.front() +
                                       " holds the finished realizations of an interrupted run; continue it with "
                                       "--resume, or discard it with --fresh");
    for (const auto& f : checkpoint_files(prefix, true)) std::filesystem::remove(f);
  }

  std::optional<OutputLock> lock_;
};

namespace detail {
inline volatile std::sig_atomic_t interrupt_requested = 0;
inline char interrupt_message[160];
inline void on_interrupt(int signal) {
  interrupt_requested = 1;
  std::signal(signal, SIG_DFL);  // a second Ctrl-C stops at once (the checkpoint stays consistent)
  const ssize_t ignored = ::write(2, interrupt_message, std::strlen(interrupt_message));
  (void)ignored;
}
}  // namespace detail

/// From here on Ctrl-C (SIGINT) and SIGTERM ask the run to stop cleanly: pass the result as
/// RunOptions::cancelled. The realizations in flight finish and are checkpointed, then the run
/// ends with granular::Cancelled, which tool::run turns into the command that resumes it.
inline std::function<bool()> stop_on_interrupt(const std::string& tool) {
  std::snprintf(detail::interrupt_message, sizeof detail::interrupt_message,
                "\n%s: stopping once the realizations in flight are saved (Ctrl-C again: stop at once)\n", tool.c_str());
  std::signal(SIGINT, detail::on_interrupt);
  std::signal(SIGTERM, detail::on_interrupt);
  return [] { return detail::interrupt_requested != 0; };
}

}  // namespace granular::tool
