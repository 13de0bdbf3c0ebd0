#pragma once
// Runs R independent realizations, each producing a vector of numbers, on threads, with
// optional checkpointing: finished realizations are logged as they complete and skipped on
// resume. Returns the rows in realization order, so any reduction over them is independent of
// thread count, interruption and resumption.
#include <cstdint>
#include <functional>
#include <vector>

#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/ensemble/progress_meter.hpp"

namespace granular {

struct EnsembleOptions {
  std::size_t realizations = 1;
  int threads = 0;                     ///< 0 = every core
  CheckpointLog* checkpoint = nullptr; ///< optional
  ProgressMeter* progress = nullptr;   ///< optional; advanced once per realization computed or loaded
};

/// `work(r, thread)` computes realization r. Rows loaded from the checkpoint are not recomputed.
std::vector<std::vector<double>> run_ensemble(
    const EnsembleOptions& options, const std::function<std::vector<double>(std::uint64_t r, int thread)>& work);

}  // namespace granular
