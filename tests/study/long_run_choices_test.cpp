// The long-run choices front ends share (study/long_run_choices.hpp): what RunOptions they give,
// and the refusals, each naming its choice.
#include "granular/study/long_run_choices.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "granular/error.hpp"

namespace granular {
namespace {

std::string refused_parameter(const LongRunChoices& o) {
  try {
    validate(o);
  } catch (const InvalidInput& e) {
    return e.parameter();
  }
  return "";
}

TEST(LongRunChoices, GiveTheRunOptionsTheySay) {
  const RunOptions run = run_options({.threads = 3, .resume_other_version = true, .skip_failed = true}, "p.checkpoint");
  EXPECT_EQ(run.threads, 3);
  EXPECT_EQ(run.checkpoint, "p.checkpoint");
  EXPECT_TRUE(run.resume) << "accepting another version's checkpoint resumes it";
  EXPECT_TRUE(run.accept_other_version);
  EXPECT_TRUE(run.skip_failed);
  EXPECT_FALSE(run.fresh);
  EXPECT_TRUE(run_options({.fresh = true}, "").fresh);
  EXPECT_FALSE(run_options({}, "").resume);
}

TEST(LongRunChoices, RefuseWhatCannotRunNamingTheChoice) {
  EXPECT_EQ(refused_parameter({.threads = -1}), "threads");
  EXPECT_EQ(refused_parameter({.threads = 4097}), "threads");
  EXPECT_EQ(refused_parameter({.threads = 4096}), "");
  EXPECT_EQ(refused_parameter({.resume = true, .fresh = true}), "fresh");
  EXPECT_EQ(refused_parameter({.resume_other_version = true, .fresh = true}), "fresh");
  EXPECT_THROW(run_options({.threads = -2}, ""), InvalidInput);
  EXPECT_TRUE(resumed_code({.resume = true}, {"no/such/checkpoint"}).is_null()) << "nothing resumed: no entry";
}

TEST(LongRunChoices, AnInterruptedRunsCheckpointIsContinuedOrDiscardedNeverOverwritten) {
  const auto dir = std::filesystem::temp_directory_path() / ("long-run-choices-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string base = (dir / "run.checkpoint").string();
  EXPECT_NO_THROW(settle_checkpoints({}, base)) << "no checkpoint: nothing to settle";
  std::ofstream(base + ".2") << "finished work";  // a study's case log
  try {
    settle_checkpoints({}, base);
    ADD_FAILURE() << "a run neither resuming nor fresh took over an interrupted run's checkpoint";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "checkpoint");
  }
  EXPECT_NO_THROW(settle_checkpoints({.resume = true}, base));
  EXPECT_TRUE(std::filesystem::exists(base + ".2")) << "resuming keeps it";
  settle_checkpoints({.fresh = true}, base);
  EXPECT_FALSE(std::filesystem::exists(base + ".2")) << "fresh discards it";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular
