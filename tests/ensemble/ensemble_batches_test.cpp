// Realizations computed several per call (run_ensemble_in_batches): the rows of run_ensemble for
// any batch and thread count, and a failure in a batch loses none of the batch's finished rows.
#include "granular/ensemble/ensemble_runner.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>

#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

std::vector<double> row_of(std::uint64_t r) { return {static_cast<double>(r), std::sqrt(static_cast<double>(r))}; }

std::vector<BatchedRow> rows_of(std::span<const std::uint64_t> rs, std::uint64_t failing = ~0ull) {
  std::vector<BatchedRow> out;
  for (const std::uint64_t r : rs)
    out.push_back(r == failing ? BatchedRow{{}, std::make_exception_ptr(NumericalError("realization failed"))}
                               : BatchedRow{row_of(r), nullptr});
  return out;
}

TEST(EnsembleBatches, TheRowsOfOneAtATimeForAnyBatchAndThreads) {
  EnsembleOptions o;
  o.realizations = 19;
  o.threads = 1;
  const auto alone = run_ensemble(o, [](std::uint64_t r, int) { return row_of(r); });
  for (const std::size_t batch : {1, 2, 4, 8, 32})
    for (const int threads : {1, 2}) {
      o.threads = threads;
      std::vector<std::size_t> sizes;  // the calls' batch sizes, in any order
      std::mutex mutex;
      const auto rows = run_ensemble_in_batches(o, batch, [&](std::span<const std::uint64_t> rs, int) {
        std::lock_guard lock(mutex);
        sizes.push_back(rs.size());
        return rows_of(rs);
      });
      EXPECT_EQ(rows, alone) << batch << " per call, " << threads << " threads";
      // Whole batches, then the rest one per call.
      std::vector<std::size_t> expected(o.realizations / batch, batch);
      expected.insert(expected.end(), o.realizations % batch, 1);
      std::sort(sizes.begin(), sizes.end(), std::greater<>());
      EXPECT_EQ(sizes, expected) << batch << " per call";
    }
}

TEST(EnsembleBatches, AFailureKeepsTheBatchsFinishedRowsAndIsRethrown) {
  const auto dir = std::filesystem::temp_directory_path() / ("ensemble-batches-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  EnsembleOptions o;
  o.realizations = 12;
  o.threads = 1;
  o.checkpoint = (dir / "run.checkpoint").string();
  EXPECT_THROW(run_ensemble_in_batches(o, 4, [](std::span<const std::uint64_t> rs, int) { return rows_of(rs, 5); }),
               NumericalError);
  const CheckpointRecords kept = CheckpointLog::load(o.checkpoint, o.parameters, false);
  for (const std::uint64_t r : {0, 1, 2, 3, 4, 6, 7}) {
    ASSERT_TRUE(kept.count(r)) << "realization " << r << " finished and was lost";
    EXPECT_EQ(kept.at(r), row_of(r));
  }
  EXPECT_FALSE(kept.count(5));
  // Resumed, the rest is computed and the kept rows are not recomputed.
  o.resume = true;
  std::vector<std::uint64_t> computed;
  const auto rows = run_ensemble_in_batches(o, 4, [&](std::span<const std::uint64_t> rs, int) {
    computed.insert(computed.end(), rs.begin(), rs.end());
    return rows_of(rs);
  });
  EXPECT_EQ(computed, (std::vector<std::uint64_t>{5, 8, 9, 10, 11}));
  for (std::uint64_t r = 0; r < 12; ++r) EXPECT_EQ(rows[r], row_of(r));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular
