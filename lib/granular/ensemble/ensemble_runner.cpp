#include "granular/ensemble/ensemble_runner.hpp"

#include "granular/ensemble/parallel_realizations.hpp"

namespace granular {

std::vector<std::vector<double>> run_ensemble(
    const EnsembleOptions& o, const std::function<std::vector<double>(std::uint64_t, int)>& work) {
  std::vector<std::vector<double>> rows(o.realizations);
  std::vector<std::uint64_t> todo;
  for (std::uint64_t r = 0; r < o.realizations; ++r) {
    if (o.checkpoint) {
      auto it = o.checkpoint->finished().find(r);
      if (it != o.checkpoint->finished().end()) {
        rows[r] = it->second;
        if (o.progress) o.progress->advance();
        continue;
      }
    }
    todo.push_back(r);
  }
  parallel_realizations(
      todo.size(), o.threads,
      [&](std::size_t i, int thread) {
        const std::uint64_t r = todo[i];
        rows[r] = work(r, thread);
        if (o.checkpoint) o.checkpoint->append(r, rows[r]);
      },
      o.progress);
  return rows;
}

}  // namespace granular
