#pragma once
// How a long computation runs, as opposed to what it computes: threads, checkpoint and resume,
// progress. Every study and ensemble takes this one type beside its own config; front ends set it
// by the rows of long_run_parameters() (the tools' --threads, --resume, ...; Python's keywords).
#include <functional>
#include <string>

#include "granular/ensemble/progress_meter.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

struct RunOptions {
  int threads = 0;                    ///< worker threads in this process; 0 = every core. Results do not depend on it.
  std::string checkpoint{};           ///< file (or prefix) logging finished realizations; empty = none
  bool resume = false;                ///< continue from `checkpoint` instead of starting afresh
  ProgressMeter* progress = nullptr;  ///< optional; advanced once per realization done
  /// Optional; polled (from any worker thread) before each realization, or each cell of the IPR
  /// map: true stops the run with granular::Cancelled once the work in flight is finished and
  /// checkpointed (how the Python module turns Ctrl-C into a resumable stop).
  std::function<bool()> cancelled{};
  /// Studies that average realizations (transport_study.hpp): a realization that fails
  /// (NumericalError) is left out of the averages and reported, instead of stopping the run.
  bool skip_failed = false;
  /// As `resume`, and accept a checkpoint another toolkit version or commit made (else refused).
  bool accept_other_version = false;
  /// Start afresh over the checkpoint an interrupted run left: without it (or `resume`) a run
  /// refuses to write over finished realizations (granular::InvalidInput naming `checkpoint`).
  bool fresh = false;
  /// Integrate the realizations one at a time rather than side by side in vector lanes, where a
  /// run can use them (spread_in_lanes.hpp: the ensembles of a splitting scheme without damping,
  /// with or without the tangent map). The results are the same bits either way; the lanes are faster.
  bool one_at_a_time = false;

  /// Whether the run continues from its checkpoint (`resume` or `accept_other_version`).
  bool resuming() const { return resume || accept_other_version; }
};

/// The rows front ends set: threads, resume, resume_other_version (accept_other_version), fresh,
/// skip_failed. The checkpoint is the front end's (a tool's PREFIX.checkpoint, Python's keyword).
const ParameterTable<RunOptions>& long_run_parameters();

/// Throws InvalidInput naming `threads` (below 0 or above 4096), `fresh` (with `resume`) or
/// `resume` (without a checkpoint to resume from).
void validate(const RunOptions& o);

}  // namespace granular
