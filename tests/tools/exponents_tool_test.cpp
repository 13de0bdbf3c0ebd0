// exponents end to end: thread and MPI-rank invariance, resume after a kill, bad input.
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tool_runner.hpp"

namespace granular::testing {
namespace {

const std::string job =
    "--N 201 --T 1e-3 --fit 4e-4:1e-3 --samples 30 --F0 10,0.1 --chains h,A,RDM2 --bootstrap 200 --compare-paper "
    "--quiet";

// Every output but the JSON (which holds the command line and the wall time).
std::string outputs(const std::string& prefix) {
  return read_file(prefix + ".csv") + read_file(prefix + "-curves.csv") + read_file(prefix + "-profiles.csv") +
         read_file(prefix + "-paper.csv");
}

TEST(ExponentsTool, ByteIdenticalForThreadCounts) {
  const std::string dir = scratch_folder("exp-threads");
  ASSERT_EQ(run_tool("exponents", job + " --realizations 6 --threads 1 --output " + dir + "/t1").exit_code, 0);
  ASSERT_EQ(run_tool("exponents", job + " --realizations 6 --threads 2 --output " + dir + "/t2").exit_code, 0);
  const std::string one = outputs(dir + "/t1");
  EXPECT_GT(one.size(), 1000u);
  EXPECT_GT(read_file(dir + "/t1-paper.csv").size(), 200u) << "the comparison must be among the outputs compared";
  EXPECT_EQ(one, outputs(dir + "/t2"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/t1.checkpoint.0")) << "checkpoints must go once the outputs exist";
  std::filesystem::remove_all(dir);
}

// --quasi: an ensemble over the phase φ (realization r draws φ from (seed, r)), the very ensemble
// `spreading --quasi --realizations R` runs, and independent of the thread count.
TEST(ExponentsTool, QuasiperiodicPhaseEnsembleIsSpreadingsAndThreadCountInvariant) {
  const std::string dir = scratch_folder("exp-quasi");
  const std::string chain =
      " --quasi s1 --modulation 0.7 --F0 10 --N 101 --T 2e-4 --fit 1e-4:2e-4 --samples 10 "
      "--realizations 4 --quiet";
  const std::string args = "--chains none --ic displacement --profile-F0 none" + chain;
  ASSERT_EQ(run_tool("exponents", args + " --threads 1 --output " + dir + "/t1").exit_code, 0);
  ASSERT_EQ(run_tool("exponents", args + " --threads 2 --output " + dir + "/t2").exit_code, 0);
  EXPECT_EQ(read_file(dir + "/t1.csv") + read_file(dir + "/t1-curves.csv"),
            read_file(dir + "/t2.csv") + read_file(dir + "/t2-curves.csv"));
  ASSERT_EQ(run_tool("spreading", chain.substr(1) + " --output " + dir + "/s").exit_code, 0);
  const auto spreading = nlohmann::json::parse(read_file(dir + "/s.json"));
  std::istringstream csv(read_file(dir + "/t1.csv"));
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_NE(row.find(",quasi-s1,"), std::string::npos) << row;
  // gamma is the fifth column (ic, F0, disorder, centre, gamma)
  std::istringstream cells(row);
  std::string cell;
  for (int i = 0; i < 5; ++i) std::getline(cells, cell, ',');
  EXPECT_EQ(std::stod(cell), spreading["gamma"].get<double>());
  std::filesystem::remove_all(dir);
}

#ifdef GRANULAR_MPIEXEC_PATH
TEST(ExponentsTool, ByteIdenticalForOneAndTwoMpiRanks) {
  const std::string dir = scratch_folder("exp-mpi");
  const std::string mpirun = std::string(GRANULAR_MPIEXEC_PATH) + " --oversubscribe -np ";
  auto run = [&](int ranks, const std::string& prefix) {
    const std::string command = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " + mpirun +
                                std::to_string(ranks) + " " + tool_path("exponents") + " " + job +
                                " --realizations 6 --threads 1 --output " + prefix + " > /dev/null 2>&1";
    return std::system(command.c_str());
  };
  ASSERT_EQ(run(1, dir + "/np1"), 0);
  ASSERT_EQ(run(2, dir + "/np2"), 0);
  EXPECT_EQ(outputs(dir + "/np1"), outputs(dir + "/np2"));
  ASSERT_EQ(run_tool("exponents", job + " --realizations 6 --output " + dir + "/plain").exit_code, 0);
  EXPECT_EQ(outputs(dir + "/np1"), outputs(dir + "/plain"));
  std::filesystem::remove_all(dir);
}
#endif

TEST(ExponentsTool, KilledRunResumesToTheSameBytes) {
  const std::string dir = scratch_folder("exp-resume");
  const std::string args = job + " --realizations 40 --threads 2";
  ASSERT_EQ(run_tool("exponents", args + " --output " + dir + "/whole").exit_code, 0);

  // Start the same run, kill -9 it once some realizations are logged, then resume.
  const std::string prefix = dir + "/cut";
  const pid_t child = fork();
  if (child == 0) {
    const std::string command =
        "exec " + tool_path("exponents") + " " + args + " --output " + prefix + " >/dev/null 2>&1";
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  bool logged = false;
  for (int i = 0; i < 2000 && !logged; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const std::string log = read_file(prefix + ".checkpoint.1");  // case 1: Anderson, F0 = 10
    logged = std::count(log.begin(), log.end(), '\n') >= 5;
  }
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(logged) << "the run never logged 5 realizations";
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before it could be killed; make it longer";
  EXPECT_FALSE(std::filesystem::exists(prefix + ".csv")) << "a killed run must leave no output";

  const ToolResult resumed = run_tool("exponents", args + " --resume --output " + prefix);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(outputs(prefix), outputs(dir + "/whole"));
  // Its JSON says it was resumed, and from which checkpoints (the cases that had one); the whole run's says nothing.
  const nlohmann::json files = nlohmann::json::parse(read_file(prefix + ".json"))["resumed_checkpoint"]["files"];
  EXPECT_NE(std::find(files.begin(), files.end(), prefix + ".checkpoint.1"), files.end()) << files;
  EXPECT_FALSE(nlohmann::json::parse(read_file(dir + "/whole.json")).contains("resumed_checkpoint"));

  // A resume with other parameters is refused, naming the parameter.
  ASSERT_EQ(run_tool("exponents", job + " --realizations 40 --output " + dir + "/other").exit_code, 0);
  {
    std::ofstream(dir + "/other.checkpoint.1") << read_file(prefix + ".csv");  // not a checkpoint
  }
  const ToolResult foreign = run_tool("exponents", job + " --realizations 40 --resume --output " + dir + "/other");
  EXPECT_EQ(foreign.exit_code, 2) << foreign.err;
  std::filesystem::remove_all(dir);
}

TEST(ExponentsTool, RefusesACheckpointOfOtherParameters) {
  const std::string dir = scratch_folder("exp-params");
  {
    std::ofstream(dir + "/x.checkpoint.0")
        << "granular-checkpoint 1 {\"F0_N\":99,\"granular_version\":\"" << GRANULAR_VERSION << "\"}\n";
  }
  const ToolResult r = run_tool("exponents", job + " --realizations 2 --resume --output " + dir + "/x");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("different parameters"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.csv"));
  std::filesystem::remove_all(dir);
}

// Errors name the flag typed; the paper's table missing is an I/O error; nothing is written.
TEST(ExponentsTool, BadInputNamesTheFlag) {
  const std::string dir = scratch_folder("exp-bad");
  const std::string base = "--N 51 --T 1e-4 --fit 2e-5:1e-4 --realizations 2 --F0 1 --quiet --output " + dir + "/x ";
  for (auto [args, flag] : {std::pair{"--chains RDM3", "--chains"},
                            {"--chains A --fit-step 3e-6 --dt 2e-6", "--fit-step"},
                            {"--chains A --centre middle", "--centre"},
                            {"--chains A --t-star nan", "--t-star"},
                            {"--chains A --bootstrap 0", "--bootstrap"},
                            {"--chains A --ic both", "--ic"}}) {
    const ToolResult r = run_tool("exponents", base + args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(flag), std::string::npos) << args << ": " << r.err;
  }
  const ToolResult missing =
      run_tool("exponents", base + "--chains A --compare-paper --paper-table /nonexistent/t.csv");
  EXPECT_EQ(missing.exit_code, 1) << missing.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.csv"));
  std::filesystem::remove_all(dir);
}

// The columns of the exponents CSV: γ about both centres, shown value, fit and mean L_d, both
// error sources; JSON holding the values used.
TEST(ExponentsTool, CsvCarriesBothCentresAndBothErrorSources) {
  const std::string dir = scratch_folder("exp-columns");
  const ToolResult r = run_tool("exponents",
                                "--N 201 --T 1e-3 --fit 4e-4:1e-3 --F0 10 --chains A --ic velocity "
                                "--realizations 4 --bootstrap 100 --quiet --output " +
                                    dir + "/x");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = read_file(dir + "/x.csv");
  EXPECT_EQ(
      csv.substr(0, csv.find('\n')),
      "ic,F0,disorder,centre,gamma,gamma_err,gamma_real_err,gamma_star,gamma_fit,gamma_fit_err,gamma_fit_real_err,"
      "gamma_mean_ld,gamma_mean_ld_err,gamma_mean_ld_real_err,worst_deviation_m2,other_centre,gamma_other,"
      "gamma_other_err,gamma_other_real_err,gamma_other_star,gamma_other_fit,gamma_other_mean_ld,eta,eta_err,"
      "eta_real_err,eta_star,eta_fit,eta_fit_err,eta_fit_real_err,eta_mean_ld,eta_mean_ld_err,eta_mean_ld_real_err,"
      "worst_deviation_ipr,realizations,max_energy_error,reached_walls");
  EXPECT_NE(csv.find("\nvelocity,10,A,site,"), std::string::npos) << csv;
  const auto meta = nlohmann::json::parse(read_file(dir + "/x.json"));
  const auto& c = meta["cases"][0];
  EXPECT_EQ(c["beta"], 8e-3);  // the paper's β, the default of both tools
  EXPECT_EQ(c["centre"], "site");
  EXPECT_TRUE(c["exponents"]["gamma_site"]["fit"]["realization_error"].is_number());
  std::filesystem::remove_all(dir);
}

// One default for every physical choice: the same case gives the same numbers from both tools.
TEST(ExponentsTool, SameCaseSameNumbersAsSpreading) {
  const std::string dir = scratch_folder("exp-spreading");
  const std::string common =
      "--N 201 --T 1e-3 --fit 4e-4:1e-3 --F0 0.1 --ic velocity --realizations 5 --bootstrap 100 --quiet";
  ASSERT_EQ(run_tool("exponents", common + " --chains RDM1 --output " + dir + "/e").exit_code, 0);
  ASSERT_EQ(run_tool("spreading", common + " --disorder RDM1 --output " + dir + "/s").exit_code, 0);
  const auto meta = nlohmann::json::parse(read_file(dir + "/s.json"));
  std::ifstream csv(dir + "/e.csv");
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  std::vector<std::string> cells;
  std::stringstream fields(row);
  for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
  ASSERT_GT(cells.size(), 25u);
  EXPECT_EQ(std::stod(cells[4]), meta["gamma"].get<double>());           // gamma (shown)
  EXPECT_EQ(std::stod(cells[6]), meta["gamma_real_err"].get<double>());  // its bootstrap error
  EXPECT_EQ(std::stod(cells[22]), meta["eta"].get<double>());
  EXPECT_EQ(meta["parameters"]["beta"], 8e-3);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular::testing
