#include "granular/ensemble/ensemble_runner.hpp"

#include <memory>

#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/error.hpp"
#include "granular/parallel/mpi_context.hpp"

namespace granular {

std::vector<std::vector<double>> run_ensemble(const EnsembleOptions& o,
                                              const std::function<std::vector<double>(std::uint64_t, int)>& work) {
  const MpiContext& mpi = MpiContext::instance();
  CheckpointRecords finished;
  // The header must equal o.parameters, which holds the realization count, so a log of another
  // run size is refused there and every record is < o.realizations.
  if (o.resume) finished = CheckpointLog::load(o.checkpoint, o.parameters, o.accept_other_version);
  // Finished realizations are never lost to a run that was not told to discard them.
  if (!o.resume && !o.fresh && !o.checkpoint.empty()) CheckpointLog::settle(o.checkpoint, false, false);
  // Every rank has read the logs before any rank rewrites its own.
  mpi.all(true);
  std::unique_ptr<CheckpointLog> log;
  if (!o.checkpoint.empty())
    log = std::make_unique<CheckpointLog>(CheckpointLog::rank_path(o.checkpoint, mpi.rank()), o.parameters,
                                          mpi.root() ? finished : CheckpointRecords{});
  mpi.all(true);

  std::vector<std::uint64_t> mine;
  std::size_t position = 0;
  for (std::uint64_t r = 0; r < o.realizations; ++r) {
    if (finished.count(r)) {
      if (o.progress && mpi.root()) o.progress->advance();
      continue;
    }
    if (position++ % static_cast<std::size_t>(mpi.size()) == static_cast<std::size_t>(mpi.rank())) mine.push_back(r);
  }
  std::vector<std::vector<double>> rows(mine.size());
  bool ok = true;
  std::exception_ptr failure;
  try {
    parallel_realizations(
        mine.size(), o.threads,
        [&](std::size_t i, int thread) {
          if (o.cancelled && o.cancelled()) throw Cancelled();
          rows[i] = work(mine[i], thread);
          if (log) log->append(mine[i], rows[i]);
        },
        o.progress);
  } catch (...) {
    ok = false;
    failure = std::current_exception();
  }
  if (!mpi.all(ok)) {
    if (failure) std::rethrow_exception(failure);
    throw NumericalError("another MPI rank failed; its message is in its own output");
  }
  auto all = mpi.gather_rows(o.realizations, mine, rows);
  if (mpi.root())
    for (auto& [r, values] : finished) all.at(r) = std::move(values);
  return all;
}

}  // namespace granular
