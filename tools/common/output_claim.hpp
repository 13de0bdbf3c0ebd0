#pragma once
// A tool claims its output prefix (io/output_claim.hpp: PREFIX.lock, rank 0 for all ranks), and
// a run that checkpoints refuses to start afresh over the checkpoint of an interrupted run
// unless told to (--fresh). A refusal is bad input (exit 2): the user asked for an output
// another run owns.
#include <filesystem>
#include <optional>
#include <string>

#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/error.hpp"
#include "granular/io/output_claim.hpp"

namespace granular::tool {

struct CheckpointPolicy {
  bool resume = false;  ///< continue from the checkpoint
  bool fresh = false;   ///< discard it and start again
};

/// The checkpoint logs of a run on `prefix`: PREFIX.checkpoint and PREFIX.checkpoint.<case>.
inline std::vector<std::string> checkpoint_files(const std::string& prefix, bool temporaries = false) {
  return CheckpointLog::files(prefix + ".checkpoint", {.cases = true, .temporaries = temporaries});
}

/// Claims `prefix`; with `checkpoints`, a run neither resuming nor fresh is refused when a
/// checkpoint is there, and a fresh one removes it.
inline OutputClaim claim_output(const std::string& prefix, const std::string& command,
                                std::optional<CheckpointPolicy> checkpoints = std::nullopt) {
  return OutputClaim(prefix, command, [&] {
    if (!checkpoints) return;
    const CheckpointPolicy& p = *checkpoints;
    if (p.resume && p.fresh) throw InvalidInput("fresh", ": not with --resume (continue, or start again: one of them)");
    const auto files = p.resume ? std::vector<std::string>{} : checkpoint_files(prefix);
    if (files.empty()) return;
    if (!p.fresh)
      throw InvalidInput("output", " '" + prefix + "': " + files.front() +
                                       " holds the finished realizations of an interrupted run; continue it with "
                                       "--resume, or discard it with --fresh");
    for (const auto& f : checkpoint_files(prefix, true)) std::filesystem::remove(f);
  });
}

}  // namespace granular::tool
