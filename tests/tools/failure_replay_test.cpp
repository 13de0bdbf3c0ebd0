// Failures a user can act on: a realization that fails stops the ensemble with a
// command that replays exactly that realization (running it gives the same failure; the case
// travels whole in a case file, `spreading --case`), every
// realization finished before it stays in the checkpoint, and --skip-failed goes on without it,
// saying so in the JSON and the final line; the means are those of the realizations kept.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "process_control.hpp"
#include "tool_runner.hpp"

namespace granular::testing {
namespace {

// A coarse step: the energy error differs from chain to chain, so a guard between the worst
// realization's error and the next one's stops exactly one realization.
const std::string chain = "--disorder A --xi 0.5 --q 0.5 --N 101 --F0 0.01 --ic velocity --seed 3";
const std::string dynamics = "--T 1e-3 --dt 2e-6 --fit 4e-4:1e-3 --samples 30 --bootstrap 50";
constexpr int realizations = 6;

std::string line_after(const std::string& text, const std::string& marker) {
  const auto at = text.find(marker);
  if (at == std::string::npos) return "";
  const auto begin = at + marker.size();
  return text.substr(begin, text.find('\n', begin) - begin);
}

/// The case file a printed replay command reads (`--case FILE`), parsed.
nlohmann::json replay_case(const std::string& replay) {
  const auto at = replay.find("--case ");
  if (at == std::string::npos) return nullptr;
  const auto begin = at + 7;
  return nlohmann::json::parse(read_file(replay.substr(begin, replay.find(' ', begin) - begin)));
}

std::vector<double> column(const std::string& csv_path, std::size_t index) {
  std::ifstream in(csv_path);
  std::string line;
  std::getline(in, line);
  std::vector<double> values;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string cell;
    for (std::size_t i = 0; i <= index; ++i) std::getline(fields, cell, ',');
    values.push_back(std::stod(cell));
  }
  return values;
}

TEST(FailureReplay, TheReplayCommandReproducesTheFailureAndSkipFailedGoesOn) {
  const std::string dir = scratch_folder("replay");
  // Each realization alone, the guard only watching: its largest energy error.
  std::vector<double> worst;
  for (int r = 0; r < realizations; ++r) {
    const std::string prefix = dir + "/single" + std::to_string(r);
    const ToolResult one = run_tool("spreading", chain + " " + dynamics + " --realization " + std::to_string(r) +
                                                     " --energy-guard warn --quiet --output " + prefix);
    ASSERT_EQ(one.exit_code, 0) << one.err;
    worst.push_back(nlohmann::json::parse(read_file(prefix + ".json"))["run"]["max_energy_error"].get<double>());
  }
  std::vector<double> sorted = worst;
  std::sort(sorted.begin(), sorted.end());
  ASSERT_GT(sorted[realizations - 1], 1.2 * sorted[realizations - 2]) << "no realization stands out; change the case";
  const double guard = std::sqrt(sorted[realizations - 1] * sorted[realizations - 2]);
  const auto failing = static_cast<long>(std::max_element(worst.begin(), worst.end()) - worst.begin());
  char guard_text[32];
  std::snprintf(guard_text, sizeof guard_text, "%.6g", guard);

  const std::string ensemble = chain + " " + dynamics + " --realizations " + std::to_string(realizations) +
                               " --threads 1 --max-energy-error " + guard_text + " --output " + dir + "/ens";
  const ToolResult stopped = run_tool("spreading", ensemble);
  ASSERT_EQ(stopped.exit_code, 3) << stopped.err;
  EXPECT_NE(stopped.err.find("realization " + std::to_string(failing) + " of seed 3"), std::string::npos) << stopped.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/ens.csv"));
  EXPECT_EQ(checkpoint_records(dir + "/ens.checkpoint"), failing) << "every realization before it is kept";

  // What it prints reproduces the failure: the same cause, at the same time, with the same error.
  const std::string replay = line_after(stopped.err, "replay it alone: ");
  ASSERT_FALSE(replay.empty()) << stopped.err;
  const std::string cause = line_after(stopped.err, "of seed 3: ");
  ASSERT_NE(cause.find("relative energy error"), std::string::npos) << stopped.err;
  const ToolResult replayed = run_printed(dir, replay);
  EXPECT_EQ(replayed.exit_code, 3) << replay << "\n" << replayed.err;
  EXPECT_EQ(line_after(replayed.err, "numerical failure: "), cause) << replay << "\n" << replayed.err;

  // exponents on the same case stops at the same realization, with the same case to replay.
  const ToolResult table =
      run_tool("exponents", "--chains A --xi 0.5 --q 0.5 --N 101 --F0 0.01 --ic velocity --seed 3 " + dynamics +
                                " --realizations 6 --threads 1 --profile-F0 none --max-energy-error " + guard_text +
                                " --quiet --output " + dir + "/table");
  EXPECT_EQ(table.exit_code, 3) << table.err;
  const std::string table_replay = line_after(table.err, "replay it alone: ");
  EXPECT_NE(table_replay.find("--realization " + std::to_string(failing) + " "), std::string::npos) << table.err;
  EXPECT_EQ(replay_case(table_replay), replay_case(replay)) << table_replay << "\n" << replay;

  // Going on without it: the printed command, run as printed.
  const std::string go_on = line_after(stopped.err, "to go on without this one: ");
  ASSERT_NE(go_on.find("--resume"), std::string::npos) << stopped.err;
  ASSERT_NE(go_on.find("--skip-failed"), std::string::npos) << stopped.err;
  const ToolResult skipped = run_printed(dir, go_on);
  ASSERT_EQ(skipped.exit_code, 0) << go_on << "\n" << skipped.err;
  EXPECT_NE(skipped.err.find("realization " + std::to_string(failing) + " failed and is left out"), std::string::npos)
      << skipped.err;
  EXPECT_NE(skipped.err.find("1 failed realization(s) of 6 left out"), std::string::npos)
      << "the final line must say it: " << skipped.err;
  const auto meta = nlohmann::json::parse(read_file(dir + "/ens.json"));
  EXPECT_EQ(meta["ensemble"]["failed_excluded"], nlohmann::json::array({failing}));
  EXPECT_EQ(meta["ensemble"]["realizations"], realizations - 1);

  // The means are those of the five realizations kept (each run alone above).
  const std::vector<double> mean = column(dir + "/ens.csv", 1);
  std::vector<double> expected(mean.size(), 0.0);
  for (int r = 0; r < realizations; ++r) {
    if (r == failing) continue;
    const std::vector<double> m2 = column(dir + "/single" + std::to_string(r) + ".csv", 1);
    ASSERT_EQ(m2.size(), mean.size());
    for (std::size_t i = 0; i < m2.size(); ++i) expected[i] += m2[i] / (realizations - 1);
  }
  for (std::size_t i = 0; i < mean.size(); ++i)
    EXPECT_NEAR(mean[i], expected[i], 1e-12 * std::fabs(expected[i])) << "sample " << i;
  std::filesystem::remove_all(dir);
}

// With --N auto the kicked bead is the centre of a chain drawn outward from it: the replay must
// keep that draw and still reproduce the failure. Found when a 100 ms study stopped on its
// energy guard and the printed command (flags, then) was refused.
TEST(FailureReplay, TheReplayCommandOfAnAutomaticallySizedChainRuns) {
  const std::string dir = scratch_folder("replay-auto");
  const ToolResult stopped =
      run_tool("spreading", "--disorder A --N auto --F0 0.01 --ic velocity --seed 3 " + dynamics +
                                " --realizations 2 --threads 1 --max-energy-error 1e-12 --output " + dir + "/ens");
  ASSERT_EQ(stopped.exit_code, 3) << stopped.err;
  const std::string replay = line_after(stopped.err, "replay it alone: ");
  const nlohmann::json replayed_case = replay_case(replay);
  ASSERT_TRUE(replayed_case.is_object()) << stopped.err;
  EXPECT_TRUE(replayed_case.contains("chain_draw")) << replayed_case.dump();
  const ToolResult replayed = run_printed(dir, replay);
  EXPECT_EQ(replayed.exit_code, 3) << replay << "\n" << replayed.err;
  EXPECT_EQ(line_after(replayed.err, "numerical failure: "), line_after(stopped.err, "of seed 3: ")) << replay << "\n"
                                                                                                     << replayed.err;
  std::filesystem::remove_all(dir);
}

// Every option family of a kicked-chain case (issue "one case, one description"): the printed
// replay command carries the whole case — damping, the tangent map, k types, polydisperse radii,
// mode kicks, matched β, each scheme — so running it meets the very failure the ensemble met
// (the same cause, time and error, to the last digit). Before, the command left these flags out
// and replayed an undamped two-type chain with a single-site kick.
struct Family {
  std::string name, flags, spelled;  ///< spelled: what the replay's case file must contain
};

void PrintTo(const Family& f, std::ostream* out) { *out << f.name << ": " << f.flags; }

class ReplayFamily : public ::testing::TestWithParam<Family> {};

TEST_P(ReplayFamily, TheReplayCommandReproducesTheFailure) {
  const Family& f = GetParam();
  const std::string dir = scratch_folder("replay-" + f.name);
  const std::string args = "--N 51 --F0 1 --seed 5 --T 1e-4 --fit 4e-5:1e-4 --samples 10 --bootstrap 20 " + f.flags +
                           " --realizations 2 --threads 1 --max-energy-error 1e-15 --output " + dir + "/ens";
  const ToolResult stopped = run_tool("spreading", args);
  ASSERT_EQ(stopped.exit_code, 3) << args << "\n" << stopped.err;
  const std::string replay = line_after(stopped.err, "replay it alone: ");
  ASSERT_NE(replay_case(replay).dump().find(f.spelled), std::string::npos) << stopped.err;
  const ToolResult replayed = run_printed(dir, replay);
  EXPECT_EQ(replayed.exit_code, 3) << replay << "\n" << replayed.err;
  const std::string cause = line_after(stopped.err, "of seed 5: ");
  ASSERT_FALSE(cause.empty()) << stopped.err;
  EXPECT_EQ(line_after(replayed.err, "numerical failure: "), cause) << replay << "\n" << replayed.err;
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(
    Families, ReplayFamily,
    ::testing::Values(Family{"plain", "--disorder RDM2 --q 0.3 --xi 0.6", R"("disorder":"RDM2")"},
                      Family{"damped", "--damping-time 2e-4", R"("damping_time":0.0002)"},
                      Family{"kk", "--kk-gamma 1e-6", R"("kk_gamma":1e-06)"},
                      Family{"types", "--types 4.76e-3:0.5,3e-3:0.3,2e-3:0.2 --disorder RDM1", R"("beads":")"},
                      Family{"masses", "--type-masses 3.6e-3:0.4,1e-3:0.6", R"("beads":")"},
                      Family{"uniform", "--polydisperse uniform:2e-3:5e-3", R"x("beads":"uniform(0.002,0.005)")x"},
                      Family{"normal", "--polydisperse normal:4e-3:5e-4:3e-3", R"("beads":"normal()"},
                      Family{"mle", "--mle --renormalize 5", R"("renormalize":5)"},
                      Family{"mode", "--ic mode --mode 20 --energy 1e-9", R"("energy":1e-09)"},
                      Family{"near", "--ic mode --near 12", R"("near_khz":12.0)"},
                      Family{"match", "--ic velocity --beta match", R"("beta":null)"},
                      Family{"aba864", "--integrator aba864", R"("integrator":"aba864")"},
                      Family{"srkn14a", "--integrator srkn14a --dt 2e-6", R"("integrator":"srkn14a")"},
                      Family{"fpu", "--force-law fpu --site 10 --centre centroid", R"("force_law":"fpu")"}),
    [](const ::testing::TestParamInfo<Family>& info) {
      std::string name = info.param.name;
      std::replace(name.begin(), name.end(), '-', '_');
      return name;
    });

}  // namespace
}  // namespace granular::testing
