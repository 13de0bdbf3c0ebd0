#pragma once
// Runs independent realizations on OpenMP threads. The work function stores its result in a
// slot indexed by the realization, and callers reduce the slots in index order afterwards, so
// results are bit-identical for any thread count. The first exception thrown by any worker
// is rethrown on the calling thread after the others stop.
#include <cstddef>
#include <functional>

#include "granular/ensemble/progress_meter.hpp"

namespace granular {

/// Number of threads to use: `requested` if > 0, else OMP_NUM_THREADS if set, else every core.
int resolve_threads(int requested);

/// Calls `work(index, thread)` for every index in [0, count); `thread` ∈ [0, threads) lets
/// workers keep per-thread scratch space. Advances `progress` (if given) once per index.
void parallel_realizations(std::size_t count, int threads,
                           const std::function<void(std::size_t index, int thread)>& work,
                           ProgressMeter* progress = nullptr);

}  // namespace granular
