#pragma once
// Runs R independent realizations, each producing a vector of numbers, on threads, with
// optional checkpointing: finished realizations are logged as they complete and skipped on
// resume. Returns the rows in realization order, so any reduction over them is independent of
// thread count, interruption and resumption.
#include <cstdint>
#include <exception>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/ensemble/progress_meter.hpp"

namespace granular {

struct EnsembleOptions {
  std::size_t realizations = 1;
  int threads = 0;         ///< per process; 0 = every core
  std::string checkpoint;  ///< log of finished realizations; empty = none
  std::string parameters =
      "{}";             ///< one-line JSON describing the run (the realization count included); a resume must match it
  bool resume = false;  ///< continue from `checkpoint` instead of starting afresh
  bool fresh = false;   ///< start afresh over it (else a run not resuming refuses: RunOptions::fresh)
  ProgressMeter* progress = nullptr;  ///< optional; advanced once per realization computed or loaded
  std::function<bool()> cancelled{};  ///< optional; true before a realization starts: throw Cancelled (run_options.hpp)
  bool accept_other_version = false;  ///< resume a checkpoint another toolkit version or commit made (else refused)
};

/// `work(r, thread)` computes realization r. Under mpirun the realizations still to do are dealt
/// round-robin to the ranks and the rows gathered on rank 0, which alone gets a non-empty result.
/// Rows loaded from the checkpoint are not recomputed. The checkpoint is left on disk: remove it
/// (CheckpointLog::remove_all) once the outputs are written.
std::vector<std::vector<double>> run_ensemble(
    const EnsembleOptions& options, const std::function<std::vector<double>(std::uint64_t r, int thread)>& work);

/// One realization's outcome in a batch: its row, or what stopped it.
struct BatchedRow {
  std::vector<double> row;
  std::exception_ptr failure;  ///< rethrown once the batch's other rows are logged
};

/// run_ensemble computing several realizations per call: `work(rs, thread)` returns one outcome
/// per element of `rs` (up to `batch` of them, in order). The rows are logged as each batch ends;
/// a failure in a batch is rethrown after its finished rows are kept. The result is run_ensemble's
/// whenever each row is a function of its realization alone.
std::vector<std::vector<double>> run_ensemble_in_batches(
    const EnsembleOptions& options, std::size_t batch,
    const std::function<std::vector<BatchedRow>(std::span<const std::uint64_t> rs, int thread)>& work);

}  // namespace granular
