#include "granular/ensemble/ensemble_runner.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <utility>

#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/error.hpp"
#include "granular/parallel/mpi_context.hpp"

namespace granular {

std::vector<std::vector<double>> run_ensemble(const EnsembleOptions& o,
                                              const std::function<std::vector<double>(std::uint64_t, int)>& work) {
  return run_ensemble_in_batches(o, 1, [&](std::span<const std::uint64_t> rs, int thread) {
    return std::vector<BatchedRow>{{work(rs[0], thread), nullptr}};
  });
}

std::vector<std::vector<double>> run_ensemble_in_batches(
    const EnsembleOptions& o, std::size_t batch,
    const std::function<std::vector<BatchedRow>(std::span<const std::uint64_t>, int)>& work) {
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
  // Whole batches, then what is left one realization per call, so that the threads share it.
  std::vector<std::pair<std::size_t, std::size_t>> calls;  // [begin, end) in `mine`
  batch = std::max<std::size_t>(batch, 1);
  std::size_t begin = 0;
  for (; begin + batch <= mine.size(); begin += batch) calls.emplace_back(begin, begin + batch);
  for (; begin < mine.size(); ++begin) calls.emplace_back(begin, begin + 1);

  std::vector<std::vector<double>> rows(mine.size());
  bool ok = true;
  std::exception_ptr failure;
  try {
    parallel_realizations(calls.size(), o.threads, [&](std::size_t c, int thread) {
      if (o.cancelled && o.cancelled()) throw Cancelled();
      const auto [from, to] = calls[c];
      const std::span<const std::uint64_t> rs(mine.data() + from, to - from);
      std::vector<BatchedRow> out = work(rs, thread);
      if (out.size() != rs.size()) throw std::logic_error("run_ensemble_in_batches: a row per realization");
      std::exception_ptr first;
      for (std::size_t i = 0; i < rs.size(); ++i) {
        if (out[i].failure) {
          if (!first) first = out[i].failure;
          continue;
        }
        rows[from + i] = std::move(out[i].row);
        if (log) log->append(rs[i], rows[from + i]);
        if (o.progress) o.progress->advance();
      }
      if (first) std::rethrow_exception(first);
    });
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
