// Runs that meet on one output prefix, with real processes: a second writer is refused while
// the first runs (naming it) and the first's outputs stay those of an undisturbed run; Ctrl-C stops
// an ensemble cleanly and prints the command that resumes it; a rerun without --resume refuses to
// discard a checkpoint unless --fresh says so.
#include <signal.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "process_control.hpp"
#include "tool_runner.hpp"

namespace granular::testing {
namespace {

const std::string claimed_exponents_args =
    "--N 201 --T 1e-3 --fit 4e-4:1e-3 --samples 30 --F0 10,0.1 --chains h,A,RDM2 --bootstrap 200 --realizations 40 "
    "--threads 2 --quiet";
const std::string claimed_spreading_args =
    "--disorder A --N 201 --T 1e-3 --fit 4e-4:1e-3 --samples 30 --F0 0.1 --realizations 60 --bootstrap 100 "
    "--threads 2";

std::string exponents_outputs(const std::string& prefix) {
  return read_file(prefix + ".csv") + read_file(prefix + "-curves.csv") + read_file(prefix + "-profiles.csv");
}

std::string spreading_outputs(const std::string& prefix) {
  return read_file(prefix + ".csv") + read_file(prefix + "-sem.csv");
}

TEST(OutputClaim, ASecondWriterIsRefusedNamingTheFirst) {
  const std::string dir = scratch_folder("claim-two");
  ASSERT_EQ(run_tool("exponents", claimed_exponents_args + " --output " + dir + "/whole").exit_code, 0);
  const std::string prefix = dir + "/p";
  const pid_t first = spawn("exec '" + tool_path("exponents") + "' " + claimed_exponents_args + " --output " + prefix +
                            " >/dev/null 2>&1");
  const std::string holder = "process " + std::to_string(first);
  ASSERT_TRUE(eventually([&] { return read_file(prefix + ".lock").find(holder) != std::string::npos; }))
      << "the first run never took " << prefix << ".lock";
  for (const std::string tool : {"exponents", "spreading"}) {  // any tool writing that prefix
    const ToolResult second =
        run_tool(tool, (tool == "exponents" ? claimed_exponents_args : claimed_spreading_args) + " --output " + prefix);
    EXPECT_EQ(second.exit_code, 2) << second.err;
    EXPECT_NE(second.err.find("is being written by " + holder), std::string::npos) << second.err;
    EXPECT_NE(second.err.find("exponents"), std::string::npos) << "the holder's command: " << second.err;
    EXPECT_NE(second.err.find("--output"), std::string::npos) << second.err;
  }
  const Ended end = wait_for(first);
  ASSERT_FALSE(end.signalled);
  EXPECT_EQ(end.code, 0);
  EXPECT_EQ(exponents_outputs(prefix), exponents_outputs(dir + "/whole")) << "the first run's outputs were disturbed";
  EXPECT_FALSE(std::filesystem::exists(prefix + ".lock")) << "a finished run removes its lock";
  std::filesystem::remove_all(dir);
}

TEST(OutputClaim, EveryToolLocksItsPrefix) {
  const std::string dir = scratch_folder("claim-all");
  // A holder that would run for long: it is killed once the others have been refused.
  std::string long_job = claimed_exponents_args;
  long_job.replace(long_job.find("--realizations 40"), 17, "--realizations 400");
  const pid_t holder =
      spawn("exec '" + tool_path("exponents") + "' " + long_job + " --output " + dir + "/x >/dev/null 2>&1");
  ASSERT_TRUE(eventually([&] { return std::filesystem::exists(dir + "/x.lock"); }));
  for (const auto& [tool, args] : {std::pair<std::string, std::string>{"ipr-map", "--N 20 --xi 0.5 --q 0.5"},
                                   {"correlations", "--N 20 --realizations 2"},
                                   {"spectrum", "--N 20"},
                                   {"localization", "--N 100 --f 1:2:1"}}) {
    const std::string out = tool == "localization" ? dir + "/x" : dir + "/x.csv";
    const ToolResult r = run_tool(tool, args + " --output " + out);
    EXPECT_EQ(r.exit_code, 2) << tool << ": " << r.err;
    EXPECT_NE(r.err.find("is being written by process " + std::to_string(holder)), std::string::npos)
        << tool << ": " << r.err;
  }
  kill(holder, SIGKILL);
  wait_for(holder);
  // A killed holder leaves its lock file, but not its lock: the next run goes ahead.
  EXPECT_TRUE(std::filesystem::exists(dir + "/x.lock"));
  const ToolResult after = run_tool("spectrum", "--N 20 --output " + dir + "/x.csv");
  EXPECT_EQ(after.exit_code, 0) << after.err;
  std::filesystem::remove_all(dir);
}

TEST(Interrupt, CtrlCStopsCleanlyPrintsTheResumeCommandAndKeepsTheCheckpoint) {
  const std::string dir = scratch_folder("ctrl-c");
  ASSERT_EQ(run_tool("spreading", claimed_spreading_args + " --quiet --output " + dir + "/whole").exit_code, 0);
  // A space in the prefix: the command printed must quote it for the shell.
  const std::string prefix = dir + "/cut here", checkpoint = prefix + ".checkpoint", quoted = "'" + prefix + "'";
  const pid_t run = spawn("exec '" + tool_path("spreading") + "' " + claimed_spreading_args + " --output " + quoted +
                          " >/dev/null 2>" + quoted + ".err");
  ASSERT_TRUE(eventually([&] { return checkpoint_records(checkpoint) >= 5; })) << "no realization was logged";
  kill(run, SIGINT);
  const Ended end = wait_for(run);
  ASSERT_FALSE(end.signalled) << "Ctrl-C must stop the run cleanly, not kill it";
  ASSERT_EQ(end.code, 130) << read_file(prefix + ".err");
  EXPECT_FALSE(std::filesystem::exists(prefix + ".csv")) << "an interrupted run writes no output";
  const long saved = checkpoint_records(checkpoint);
  ASSERT_GE(saved, 5);
  ASSERT_LT(saved, 60) << "the run finished before the interrupt; make it longer";
  std::string err = read_file(prefix + ".err");
  while (!err.empty() && err.back() == '\n') err.pop_back();
  const std::string command = err.substr(err.rfind('\n') + 1);
  EXPECT_NE(err.find("To continue"), std::string::npos) << err;
  const std::string expected =
      tool_path("spreading") + " " + claimed_spreading_args + " --output " + quoted + " --resume";
  EXPECT_EQ(command, expected) << "the original command, shell-quoted, with --resume: " << err;

  // A rerun without --resume refuses to discard the finished realizations.
  const std::string kept = read_file(checkpoint);
  const ToolResult again = run_tool("spreading", claimed_spreading_args + " --quiet --output " + quoted);
  EXPECT_EQ(again.exit_code, 2) << again.err;
  EXPECT_NE(again.err.find("--resume"), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("--fresh"), std::string::npos) << again.err;
  EXPECT_EQ(read_file(checkpoint), kept) << "a refused run must leave the checkpoint alone";
  EXPECT_FALSE(std::filesystem::exists(prefix + ".csv"));

  // The printed command, pasted into a shell, finishes the run as if it had never stopped.
  const ToolResult resumed = run_printed(dir, command);
  ASSERT_EQ(resumed.exit_code, 0) << command << "\n" << resumed.err;
  EXPECT_EQ(spreading_outputs(prefix), spreading_outputs(dir + "/whole"));
  EXPECT_FALSE(std::filesystem::exists(checkpoint));

  // --fresh discards a checkpoint (here: the interrupted run's, put back) and starts again.
  { std::ofstream(checkpoint) << kept; }
  const ToolResult fresh = run_tool("spreading", claimed_spreading_args + " --quiet --fresh --output " + quoted);
  EXPECT_EQ(fresh.exit_code, 0) << fresh.err;
  EXPECT_EQ(spreading_outputs(prefix), spreading_outputs(dir + "/whole"));
  EXPECT_EQ(run_tool("spreading", claimed_spreading_args + " --resume --fresh --output " + dir + "/y").exit_code, 2);
  std::filesystem::remove_all(dir);
}

TEST(OutputClaim, FreshRemovesOnlyTheCheckpointsARunWrites) {
  const std::string dir = scratch_folder("fresh-own"), prefix = dir + "/run";
  const std::string job =
      "--disorder A --N 101 --T 5e-4 --samples 20 --F0 0.1 --realizations 3 --bootstrap 20 --threads 1 --quiet";
  for (const std::string tail : {"", ".rank1", ".0", ".0.rank2", ".tmp.12345", ".bak", ".old.1", ".rank1.orig"})
    std::ofstream(prefix + ".checkpoint" + tail) << "content of " << tail << "\n";
  const ToolResult r = run_tool("spreading", job + " --fresh --output " + prefix);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string gone : {"", ".rank1", ".0", ".0.rank2", ".tmp.12345"})
    EXPECT_FALSE(std::filesystem::exists(prefix + ".checkpoint" + gone)) << gone;
  for (const std::string kept : {".bak", ".old.1", ".rank1.orig"})  // the user's own files
    EXPECT_EQ(read_file(prefix + ".checkpoint" + kept), "content of " + kept + "\n");
  std::filesystem::remove_all(dir);
}

TEST(OutputClaim, AKilledRunsHeaderTemporaryIsNotACheckpoint) {
  // A kill between creating the checkpoint header's temporary and renaming it leaves only
  // PREFIX.checkpoint.tmp.<pid>: nothing was finished, so --resume is refused saying so, and a run
  // without it goes ahead and clears the leftover.
  const std::string dir = scratch_folder("header-temporary"), prefix = dir + "/run";
  const std::string job =
      "--disorder A --N 101 --T 5e-4 --samples 20 --F0 0.1 --realizations 3 --bootstrap 20 --threads 1 --quiet";
  const std::string leftover = prefix + ".checkpoint.tmp.4242";
  std::ofstream(leftover) << "#granular-checkpoint {\"half\n";
  const ToolResult resumed = run_tool("spreading", job + " --resume --output " + prefix);
  EXPECT_EQ(resumed.exit_code, 2) << resumed.err;
  EXPECT_NE(resumed.err.find("stopped before it finished anything"), std::string::npos) << resumed.err;
  EXPECT_EQ(std::count(resumed.err.begin(), resumed.err.end(), '\n'), 1) << resumed.err;
  EXPECT_FALSE(std::filesystem::exists(prefix + ".csv"));
  const ToolResult again = run_tool("spreading", job + " --output " + prefix);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(std::filesystem::exists(prefix + ".csv"));
  EXPECT_FALSE(std::filesystem::exists(leftover));
  std::filesystem::remove_all(dir);
}

TEST(OutputClaim, ASymlinkAtTheLockIsRefusedAndItsTargetKept) {
  const std::string dir = scratch_folder("lock-link"), victim = dir + "/victim";
  std::ofstream(victim) << "a file of the user's\n";
  std::filesystem::create_symlink(victim, dir + "/out.lock");  // --output out.csv: the prefix is out
  const ToolResult r = run_tool("spectrum", "--N 20 --output " + dir + "/out.csv");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("symbolic link"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(read_file(victim), "a file of the user's\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.csv"));
  std::filesystem::remove_all(dir);
}

TEST(CheckpointVersion, ACheckpointOfAnotherVersionIsRefusedUnlessAccepted) {
  const std::string dir = scratch_folder("other-version");
  ASSERT_EQ(run_tool("spreading", claimed_spreading_args + " --quiet --output " + dir + "/whole").exit_code, 0);
  const std::string prefix = dir + "/run", checkpoint = prefix + ".checkpoint";
  const pid_t run = spawn("exec '" + tool_path("spreading") + "' " + claimed_spreading_args + " --quiet --output " +
                          prefix + " >/dev/null 2>&1");
  ASSERT_TRUE(eventually([&] { return checkpoint_records(checkpoint) >= 3; })) << "no realization was logged";
  kill(run, SIGKILL);
  wait_for(run);
  // The same checkpoint as if an earlier release had written it.
  std::string text = read_file(checkpoint);
  const std::string ours = std::string("\"granular_version\":\"") + GRANULAR_VERSION + "\"";
  ASSERT_NE(text.find(ours), std::string::npos) << "the header records the version: " << text.substr(0, 300);
  ASSERT_NE(text.find("\"granular_commit\":\""), std::string::npos) << "and the commit";
  text.replace(text.find(ours), ours.size(), "\"granular_version\":\"0.0.9\"");
  { std::ofstream(checkpoint, std::ios::binary) << text; }

  const ToolResult refused = run_tool("spreading", claimed_spreading_args + " --quiet --resume --output " + prefix);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("granular 0.0.9"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find(std::string("this is granular ") + GRANULAR_VERSION), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--resume-other-version"), std::string::npos) << refused.err;
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_EQ(read_file(checkpoint), text) << "a refused resume leaves the checkpoint alone";
  EXPECT_FALSE(std::filesystem::exists(prefix + ".csv"));

  const ToolResult accepted =
      run_tool("spreading", claimed_spreading_args + " --quiet --resume-other-version --output " + prefix);
  ASSERT_EQ(accepted.exit_code, 0) << accepted.err;
  EXPECT_EQ(spreading_outputs(prefix), spreading_outputs(dir + "/whole"));
  const std::string json = read_file(prefix + ".json");
  EXPECT_NE(json.find("\"resumed_checkpoint\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"made_by\": \"0.0.9 (commit "), std::string::npos) << json;
  EXPECT_NE(json.find(std::string("\"resumed_by\": \"") + GRANULAR_VERSION + " (commit "), std::string::npos) << json;
  const nlohmann::json versions = nlohmann::json::parse(json)["resumed_checkpoint"]["versions"];  // both, oldest first
  ASSERT_EQ(versions.size(), 2u) << json;
  EXPECT_EQ(versions[0].get<std::string>().rfind("0.0.9 (commit ", 0), 0u) << json;
  EXPECT_EQ(versions[1].get<std::string>().rfind(std::string(GRANULAR_VERSION) + " (commit ", 0), 0u) << json;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular::testing
