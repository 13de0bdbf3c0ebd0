// How a long run goes, as front ends set it by the rows of long_run_parameters(): the refusals,
// each naming its parameter, and an interrupted run's checkpoint continued or discarded, never
// overwritten (ensemble/resumed_checkpoint.hpp).
#include "granular/ensemble/run_options.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "granular/ensemble/resumed_checkpoint.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

std::string refused_parameter(const RunOptions& o) {
  try {
    validate(o);
  } catch (const InvalidInput& e) {
    return e.parameter();
  }
  return "";
}

TEST(RunOptions, TheRowsSetTheFieldsTheyName) {
  RunOptions o;
  const auto& table = long_run_parameters();
  std::get<Ref<RunOptions, int>>(parameter(table, "threads").field)(o) = 3;
  std::get<Ref<RunOptions, bool>>(parameter(table, "resume_other_version").field)(o) = true;
  EXPECT_EQ(o.threads, 3);
  EXPECT_TRUE(o.accept_other_version);
  EXPECT_TRUE(o.resuming()) << "accepting another version's checkpoint resumes it";
  EXPECT_FALSE(o.resume);
  EXPECT_FALSE(RunOptions{}.resuming());
}

TEST(RunOptions, RefuseWhatCannotRunNamingTheParameter) {
  EXPECT_EQ(refused_parameter({.threads = -1}), "threads");
  EXPECT_EQ(refused_parameter({.threads = 4097}), "threads");
  EXPECT_EQ(refused_parameter({.threads = 4096}), "");
  EXPECT_EQ(refused_parameter({.checkpoint = "p", .resume = true, .fresh = true}), "fresh");
  EXPECT_EQ(refused_parameter({.checkpoint = "p", .accept_other_version = true, .fresh = true}), "fresh");
  EXPECT_EQ(refused_parameter({.resume = true}), "resume") << "nothing to resume from";
  EXPECT_EQ(refused_parameter({.checkpoint = "p", .resume = true}), "");
  EXPECT_TRUE(resumed_code({.checkpoint = "p", .resume = true}, {"no/such/checkpoint"}).is_null())
      << "nothing resumed: no entry";
}

TEST(RunOptions, AnInterruptedRunsCheckpointIsContinuedOrDiscardedNeverOverwritten) {
  const auto dir = std::filesystem::temp_directory_path() / ("run-options-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string base = (dir / "run.checkpoint").string();
  EXPECT_NO_THROW(settle_checkpoints({.checkpoint = base}, base)) << "no checkpoint: nothing to settle";
  std::ofstream(base + ".2") << "finished work";  // a study's case log
  try {
    settle_checkpoints({.checkpoint = base}, base);
    ADD_FAILURE() << "a run neither resuming nor fresh took over an interrupted run's checkpoint";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "checkpoint");
  }
  EXPECT_NO_THROW(settle_checkpoints({.checkpoint = base, .resume = true}, base));
  EXPECT_TRUE(std::filesystem::exists(base + ".2")) << "resuming keeps it";
  settle_checkpoints({.checkpoint = base, .fresh = true}, base);
  EXPECT_FALSE(std::filesystem::exists(base + ".2")) << "fresh discards it";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular
