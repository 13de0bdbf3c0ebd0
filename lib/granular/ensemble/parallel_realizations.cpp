#include "granular/ensemble/parallel_realizations.hpp"

#include <omp.h>

#include <atomic>
#include <exception>
#include <mutex>

namespace granular {

// omp_get_max_threads() is OMP_NUM_THREADS when set, else every core: a user's limit is kept.
int resolve_threads(int requested) { return requested > 0 ? requested : omp_get_max_threads(); }

void parallel_realizations(std::size_t count, int threads, const std::function<void(std::size_t, int)>& work,
                           ProgressMeter* progress) {
  std::exception_ptr failure;
  std::mutex failure_mutex;
  std::atomic<bool> stop{false};
  const auto n = static_cast<long>(count);
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolve_threads(threads))
  for (long i = 0; i < n; ++i) {
    if (stop.load(std::memory_order_relaxed)) continue;
    try {
      work(static_cast<std::size_t>(i), omp_get_thread_num());
      if (progress) progress->advance();
    } catch (...) {
      std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      stop = true;
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace granular
