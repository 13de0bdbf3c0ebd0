#include "granular/ensemble/checkpoint_log.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include <gtest/gtest.h>

#include "granular/code_identity.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

std::string temp_path(const char* name) {
  return (std::filesystem::temp_directory_path() / (std::string("granular-ckpt-") + name + std::to_string(::getpid())))
      .string();
}

TEST(CheckpointLog, RoundTripsValuesExactlyAndResumes) {
  const std::string path = temp_path("roundtrip");
  const std::vector<double> a{0.1, 1e-300, -3.5, 1.0 / 3.0, std::numeric_limits<double>::quiet_NaN()}, b{2.0};
  {
    CheckpointLog log(path, R"({"N":10,"seed":1})");
    log.append(3, a);
    log.append(0, b);
  }
  const CheckpointRecords resumed = CheckpointLog::load(path, R"({"N":10,"seed":1})");
  ASSERT_EQ(resumed.size(), 2u);
  const auto& got = resumed.at(3);
  ASSERT_EQ(got.size(), a.size());
  for (std::size_t i = 0; i + 1 < a.size(); ++i) EXPECT_EQ(got[i], a[i]);  // bit-exact
  EXPECT_TRUE(std::isnan(got.back()));
  EXPECT_EQ(resumed.at(0), b);
  {
    CheckpointLog rank1(CheckpointLog::rank_path(path, 1), R"({"N":10,"seed":1})");
    rank1.append(5, b);
  }
  EXPECT_EQ(CheckpointLog::load(path, R"({"N":10,"seed":1})").size(), 3u);  // rank files are read too
  CheckpointLog::remove_all(path);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".rank1"));
}

TEST(CheckpointLog, IgnoresATornLastLineAndCorruptedRecords) {
  const std::string path = temp_path("torn");
  {
    CheckpointLog log(path, "{}");
    log.append(0, {1.0, 2.0});
    log.append(1, {3.0, 4.0});
  }
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto second = text.find("\n1 ");
  ASSERT_NE(second, std::string::npos);
  std::string edited = text;
  edited[second + 5] = '9';  // change a value of record 1: checksum mismatch
  edited += "2 2 5 6";       // a torn line without newline
  { std::ofstream(path, std::ios::trunc) << edited; }
  const CheckpointRecords resumed = CheckpointLog::load(path, "{}");
  EXPECT_EQ(resumed.size(), 1u);
  EXPECT_TRUE(resumed.count(0));
  CheckpointLog::remove_all(path);
}

TEST(CheckpointLog, RemoveAllTakesTheTemporariesOfKilledRunsAndNothingElse) {
  const std::string path = temp_path("family");
  { CheckpointLog log(path, "{}"); }
  const std::vector<std::string> theirs = {path + ".tmp.4242", path + ".rank1", path + ".rank1.tmp.77"};
  const std::vector<std::string> users = {path + ".bak", path + ".tmp.old", path + ".rank1.orig", path + "x.tmp.12",
                                          path + ".tmp."};
  for (const auto& f : theirs) std::ofstream(f) << "x";
  for (const auto& f : users) std::ofstream(f) << "x";
  CheckpointLog::remove_all(path);
  EXPECT_FALSE(std::filesystem::exists(path));
  for (const auto& f : theirs) EXPECT_FALSE(std::filesystem::exists(f)) << f;
  for (const auto& f : users) {
    EXPECT_TRUE(std::filesystem::exists(f)) << f;
    std::filesystem::remove(f);
  }
}

TEST(CheckpointLog, ThisCodeIsNamedAsTheMakerOfItsLogs) {
  const std::string path = temp_path("this-code");
  { CheckpointLog log(path, "{}"); }
  EXPECT_EQ(CheckpointLog::this_code(), std::string(code_version()) + " (commit " + code_commit() + ")");
  EXPECT_EQ(CheckpointLog::code_of(path), CheckpointLog::this_code());
  CheckpointLog::remove_all(path);
}

// The log at `path` as if `version` had written it: this code's version replaced in its header,
// also where a list of contributors names this code (the records kept).
void checkpoint_log_rewritten_by(const std::string& path, const std::string& version) {
  std::ifstream in(path, std::ios::binary);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string ours = std::string("\"granular_version\":\"") + code_version() + "\"";
  const std::size_t at = text.find(ours);
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, ours.size(), "\"granular_version\":\"" + version + "\"");
  const std::string listed = std::string("\"") + code_version() + " (commit ";
  if (const std::size_t in_list = text.find(listed); in_list != std::string::npos && in_list < text.find('\n'))
    text.replace(in_list, listed.size(), "\"" + version + " (commit ");
  std::ofstream(path, std::ios::binary) << text;
}

// Two resumes accepted across versions: 0.0.8 made the log, 0.0.9 resumed it, this code resumes it
// again. Every one of them made records, and the log names all three, oldest first.
TEST(CheckpointLog, EveryVersionThatContributedIsListedAfterTwoAcceptedResumes) {
  const std::string path = temp_path("contributors"), parameters = R"({"N":10,"seed":1})";
  const std::string commit = std::string(" (commit ") + code_commit() + ")";
  {
    CheckpointLog log(path, parameters);
    log.append(0, {1.0});
  }
  checkpoint_log_rewritten_by(path, "0.0.8");
  EXPECT_EQ(CheckpointLog::codes_of(path), (std::vector<std::string>{"0.0.8" + commit}));
  {  // resumed by "0.0.9" (this code, renamed below)
    CheckpointLog log(path, parameters, CheckpointLog::load(path, parameters, true));
    log.append(1, {2.0});
  }
  checkpoint_log_rewritten_by(path, "0.0.9");
  EXPECT_EQ(CheckpointLog::codes_of(path), (std::vector<std::string>{"0.0.8" + commit, "0.0.9" + commit}));
  EXPECT_THROW(CheckpointLog::load(path, parameters), InvalidInput);  // not accepted: refused
  {
    CheckpointLog log(path, parameters, CheckpointLog::load(path, parameters, true));
    log.append(2, {3.0});
  }
  EXPECT_EQ(CheckpointLog::code_of(path), CheckpointLog::this_code());
  EXPECT_EQ(CheckpointLog::codes_of(path),
            (std::vector<std::string>{"0.0.8" + commit, "0.0.9" + commit, CheckpointLog::this_code()}));
  const CheckpointRecords all = CheckpointLog::load(path, parameters);  // this code's own: no acceptance needed
  EXPECT_EQ(all.size(), 3u);
  CheckpointLog::remove_all(path);
}

// The log at `path` as if this version built from commit `commit` had written it (instead of
// commit `was`, this code's by default).
void checkpoint_log_rewritten_by_commit(const std::string& path, const std::string& commit,
                                        const std::string& was = code_commit()) {
  std::ifstream in(path, std::ios::binary);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string ours = "\"granular_commit\":\"" + was + "\"";
  const std::size_t at = text.find(ours);
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, ours.size(), "\"granular_commit\":\"" + commit + "\"");
  std::ofstream(path, std::ios::binary) << text;
}

// The version string alone changes only with releases: a log another commit of the same version
// made is another code's, refused naming both commits unless accepted. A log whose commit is
// "unknown" (built outside git) cannot be told apart and is taken as this code's.
TEST(CheckpointLog, ALogOfAnotherCommitOfTheSameVersionIsRefusedNamingBoth) {
  if (std::string(code_commit()) == "unknown") GTEST_SKIP() << "built outside git: no commit to compare";
  const std::string path = temp_path("other-commit"), parameters = R"({"N":10,"seed":1})";
  {
    CheckpointLog log(path, parameters);
    log.append(0, {1.0});
  }
  checkpoint_log_rewritten_by_commit(path, "0123456789ab");
  try {
    CheckpointLog::load(path, parameters);
    ADD_FAILURE() << "a log of another commit was resumed";
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("(commit 0123456789ab)"), std::string::npos) << what;
    EXPECT_NE(what.find(std::string("(commit ") + code_commit() + ")"), std::string::npos) << what;
    EXPECT_NE(what.find("resume_other_version"), std::string::npos) << what;
  }
  EXPECT_NE(CheckpointLog::other_version(path), "");
  EXPECT_EQ(CheckpointLog::load(path, parameters, true).size(), 1u);  // accepted when told

  checkpoint_log_rewritten_by_commit(path, "unknown", "0123456789ab");
  EXPECT_EQ(CheckpointLog::other_version(path), "");
  EXPECT_EQ(CheckpointLog::load(path, parameters).size(), 1u);
  CheckpointLog::remove_all(path);
}

// A resume by the same code keeps the header as it was: no list of one.
TEST(CheckpointLog, ASameVersionResumeListsNoContributors) {
  const std::string path = temp_path("same-code"), parameters = R"({"N":10,"seed":1})";
  {
    CheckpointLog log(path, parameters);
    log.append(0, {1.0});
  }
  { CheckpointLog log(path, parameters, CheckpointLog::load(path, parameters)); }
  std::ifstream in(path, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_EQ(text.find("granular_contributors"), std::string::npos) << text;
  EXPECT_EQ(CheckpointLog::codes_of(path), (std::vector<std::string>{CheckpointLog::this_code()}));
  CheckpointLog::remove_all(path);
}

TEST(CheckpointLog, FilesNameExactlyTheMembersAskedFor) {
  const std::string base = temp_path("members");
  const std::vector<std::string> logs = {base, base + ".rank1", base + ".rank12"};
  const std::vector<std::string> cases = {base + ".0", base + ".3", base + ".3.rank2"};
  const std::vector<std::string> temporaries = {base + ".tmp.42", base + ".rank1.tmp.7", base + ".3.tmp.9",
                                                base + ".3.rank2.tmp.11"};
  const std::vector<std::string> users = {base + ".bak",       base + ".rankx", base + ".3x",
                                          base + ".rank1.bak", base + ".tmp.",  base + "x.rank1",
                                          base + ".tmp.9a",    base + ".",      base + ".rank"};
  for (const auto* group : {&logs, &cases, &temporaries, &users})
    for (const auto& f : *group) std::ofstream(f) << "x";
  const auto sorted = [](std::vector<std::string> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  const auto joined = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  EXPECT_EQ(CheckpointLog::files(base, {}), sorted(logs));
  EXPECT_EQ(CheckpointLog::files(base, {.cases = true}), sorted(joined(logs, cases)));
  EXPECT_EQ(CheckpointLog::files(base, {.temporaries = true}),
            sorted(joined(logs, {base + ".tmp.42", base + ".rank1.tmp.7"})));
  EXPECT_EQ(CheckpointLog::files(base, {.cases = true, .temporaries = true}),
            sorted(joined(joined(logs, cases), temporaries)));
  EXPECT_TRUE(CheckpointLog::exists(base));
  for (const auto* group : {&logs, &cases, &temporaries, &users})
    for (const auto& f : *group) std::filesystem::remove(f);
  EXPECT_TRUE(CheckpointLog::files(base, {.cases = true, .temporaries = true}).empty());
}

TEST(CheckpointLog, ASymlinkAtItsTemporaryNamesIsNotFollowed) {
  // The fixed PATH.tmp it once used and the PATH.tmp.<pid> of every temporary now, each pointing
  // at a file of the user's: the log is written around them and the victim is untouched.
  const std::string path = temp_path("planted"), victim = path + ".victim";
  const std::string text = "a file of the user's\n";
  std::ofstream(victim, std::ios::binary) << text;
  for (const std::string& planted : {path + ".tmp", path + ".tmp." + std::to_string(::getpid())}) {
    std::filesystem::create_symlink(victim, planted);
    {
      CheckpointLog log(path, "{}", {{0, {1.5}}});
      log.append(1, {2.5});
    }
    EXPECT_EQ(CheckpointLog::load(path, "{}").size(), 2u);
    std::ifstream in(victim, std::ios::binary);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), text) << "through " << planted;
    std::filesystem::remove(planted);
    CheckpointLog::remove_all(path);
  }
  std::filesystem::remove(victim);
}

TEST(CheckpointLog, RefusesACheckpointOfOtherParameters) {
  const std::string path = temp_path("params");
  { CheckpointLog log(path, R"({"F0":10,"N":100})"); }
  try {
    CheckpointLog::load(path, R"({"F0":0.5,"N":100})");
    FAIL() << "accepted a checkpoint made with another F0";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("F0"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
  EXPECT_THROW(CheckpointLog::load(path, "{}"), InvalidInput);  // nothing to resume
  { std::ofstream(path) << "hello\n"; }
  EXPECT_THROW(CheckpointLog::load(path, "{}"), InvalidInput);  // not a checkpoint
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace granular

#include "granular/ensemble/ensemble_runner.hpp"

namespace granular {
namespace {

TEST(EnsembleRunner, ResumedRunSkipsFinishedRealizationsAndEqualsAFreshOne) {
  const std::string path = temp_path("runner");
  auto work = [](std::uint64_t r, int) {
    return std::vector<double>{std::sqrt(static_cast<double>(r)), 1.0 / (1.0 + static_cast<double>(r))};
  };
  EnsembleOptions fresh_options;
  fresh_options.realizations = 20;
  fresh_options.threads = 2;
  const auto fresh = run_ensemble(fresh_options, work);

  // "Interrupted" run: only the first 7 realizations made it into the log.
  {
    CheckpointLog log(path, "{}");
    for (std::uint64_t r = 0; r < 7; ++r) log.append(r, work(r, 0));
  }
  std::atomic<int> computed{0};
  EnsembleOptions resumed_options = fresh_options;
  resumed_options.threads = 1;
  resumed_options.checkpoint = path;
  resumed_options.resume = true;
  const auto resumed = run_ensemble(resumed_options, [&](std::uint64_t r, int t) {
    ++computed;
    return work(r, t);
  });
  EXPECT_EQ(computed.load(), 13);
  EXPECT_EQ(resumed, fresh);
  EXPECT_EQ(CheckpointLog::load(path, "{}").size(), 20u);  // the log now holds every realization
  CheckpointLog::remove_all(path);
}

// The cancellation hook (how Python's Ctrl-C stops an ensemble): once `cancelled` says so, no new
// realization starts, the ones already done stay in the log, and a resume gives the fresh rows.
TEST(EnsembleRunner, CancelledRunKeepsFinishedRealizationsAndResumesToTheFreshResult) {
  const std::string path = temp_path("cancel");
  auto work = [](std::uint64_t r, int) {
    return std::vector<double>{std::exp(-static_cast<double>(r)), static_cast<double>(r)};
  };
  EnsembleOptions options;
  options.realizations = 30;
  options.threads = 2;
  const auto fresh = run_ensemble(options, work);

  std::atomic<int> started{0};
  options.checkpoint = path;
  options.cancelled = [&] { return started.load() >= 9; };
  EXPECT_THROW(run_ensemble(options,
                            [&](std::uint64_t r, int t) {
                              ++started;
                              return work(r, t);
                            }),
               Cancelled);
  const std::size_t kept = CheckpointLog::load(path, "{}").size();
  EXPECT_GE(kept, 9u);  // every started realization finished and was logged
  EXPECT_LT(kept, 30u);
  EXPECT_EQ(kept, static_cast<std::size_t>(started.load()));

  options.cancelled = nullptr;
  // Not resuming: refused, naming the checkpoint, and the finished realizations stay; unless fresh.
  try {
    run_ensemble(options, work);
    ADD_FAILURE() << "a run not resuming wrote over an interrupted run's checkpoint";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "checkpoint");
  }
  EXPECT_EQ(CheckpointLog::load(path, "{}").size(), kept);
  options.resume = true;
  EXPECT_EQ(run_ensemble(options, work), fresh);
  options.resume = false, options.fresh = true;
  EXPECT_EQ(run_ensemble(options, work), fresh);
  CheckpointLog::remove_all(path);
}

}  // namespace
}  // namespace granular
