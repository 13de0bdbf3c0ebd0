// `exponents` and `correlations` beyond the paper's kinds: chains of k bead types
// or polydisperse radii, mode-shaped kicks and the maximal Lyapunov exponent, each checked
// against an independent route to the same numbers (the paper's kinds, `spreading` runs).
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tool_runner.hpp"

namespace granular::testing {
namespace {

using Table = std::map<std::string, std::vector<std::string>>;  // column → cells, as written

Table read_table(const std::string& path) {
  std::istringstream in(read_file(path));
  std::string line, cell;
  std::vector<std::string> names;
  Table t;
  for (bool header = true; std::getline(in, line); header = false) {
    std::istringstream row(line);
    for (std::size_t i = 0; std::getline(row, cell, ','); ++i) {
      if (header) names.push_back(cell), t[cell];
      else t[names.at(i)].push_back(cell);
    }
  }
  return t;
}

double number(const std::string& cell) { return std::stod(cell); }

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

const std::string dynamics = "--N 201 --T 1e-3 --fit 4e-4:1e-3 --samples 30 --F0 10 --quiet";
const std::string study = dynamics + " --bootstrap 50 --profile-F0 10 --profile-realizations 2";

std::string outputs(const std::string& prefix) {
  return read_file(prefix + ".csv") + read_file(prefix + "-curves.csv") + read_file(prefix + "-profiles.csv");
}

// Two types given as --types (radii R1 and ξR1 with probabilities q, 1 − q) draw the chains of
// --q q --xi ξ bit for bit, so the study gives the same bytes under the chain's own name.
TEST(ExponentsChains, TwoTypesAreThePapersKindBitForBit) {
  const std::string dir = scratch_folder("exp-types");
  for (const std::string kind : {"A", "RDM1"}) {
    const std::string args = study + " --realizations 4 --ic displacement,velocity";
    ASSERT_EQ(run_tool("exponents", args + " --chains " + kind + " --q 0.3 --output " + dir + "/paper").exit_code, 0);
    ASSERT_EQ(run_tool("exponents", args + " --chains none --types 4.76e-3:0.3,2.38e-3:0.7 --types-rule " + kind +
                                        " --chain-name mine --output " + dir + "/mine")
                  .exit_code,
              0);
    const std::string paper = outputs(dir + "/paper");
    EXPECT_GT(paper.size(), 2000u);
    EXPECT_EQ(replace_all(paper, "," + kind + ",", ",mine,"), outputs(dir + "/mine")) << kind;
    const auto meta = nlohmann::json::parse(read_file(dir + "/mine.json"));
    EXPECT_EQ(meta["cases"][0]["chain"], "mine");
    EXPECT_EQ(meta["cases"][0]["beads"], "types(" + kind + ";0.00476:0.3,0.00238:0.7)");
  }
  std::filesystem::remove_all(dir);
}

// exponents --mle: each realization's X1(T) is what spreading --mle gives for it; the columns are
// their mean, its standard error and their spread.
TEST(ExponentsChains, MleIsTheMeanOfSpreadingRuns) {
  const std::string dir = scratch_folder("exp-mle");
  const int realizations = 3;
  ASSERT_EQ(run_tool("exponents", study + " --chains A --ic velocity --mle --realizations " +
                                      std::to_string(realizations) + " --output " + dir + "/e")
                .exit_code,
            0);
  std::vector<double> x1;
  for (int r = 0; r < realizations; ++r) {
    const std::string prefix = dir + "/s" + std::to_string(r);
    ASSERT_EQ(run_tool("spreading", dynamics + " --disorder A --ic velocity --mle --realization " + std::to_string(r) +
                                        " --output " + prefix)
                  .exit_code,
              0);
    x1.push_back(number(read_table(prefix + ".csv").at("mle").back()));
  }
  double mean = 0, square = 0;
  for (double x : x1) mean += x / realizations;
  for (double x : x1) square += (x - mean) * (x - mean);
  const double sd = std::sqrt(square / (realizations - 1));
  const Table e = read_table(dir + "/e.csv");
  ASSERT_EQ(e.at("mle").size(), 1u);
  EXPECT_GT(mean, 0);
  EXPECT_NEAR(number(e.at("mle")[0]), mean, 1e-12 * mean);
  EXPECT_NEAR(number(e.at("mle_sd")[0]), sd, 1e-9 * sd);
  EXPECT_NEAR(number(e.at("mle_real_err")[0]), sd / std::sqrt(realizations), 1e-9 * sd);
  const Table curves = read_table(dir + "/e-curves.csv");
  EXPECT_EQ(curves.at("mle").back(), e.at("mle")[0]);
  EXPECT_EQ(curves.at("mle_se").size(), curves.at("t").size());
  const auto meta = nlohmann::json::parse(read_file(dir + "/e.json"));
  EXPECT_EQ(meta["cases"][0]["mle_at_T"]["X1_at_T_per_s"], number(e.at("mle")[0]));
  // Without --mle the columns stay those of a conservative study.
  ASSERT_EQ(
      run_tool("exponents", study + " --chains A --ic velocity --realizations 2 --output " + dir + "/plain").exit_code,
      0);
  EXPECT_EQ(read_table(dir + "/plain.csv").count("mle"), 0u);
  std::filesystem::remove_all(dir);
}

// exponents --ic mode runs the ensemble spreading --ic mode runs, with the same mode options.
TEST(ExponentsChains, ModeKickIsSpreadingsModeKick) {
  const std::string dir = scratch_folder("exp-mode");
  const std::string mode = " --ic mode --near 20 --energy 1e-7 --realizations 3";
  ASSERT_EQ(run_tool("exponents", study + " --chains A" + mode + " --output " + dir + "/e").exit_code, 0);
  ASSERT_EQ(run_tool("spreading", dynamics + " --disorder A" + mode + " --output " + dir + "/s").exit_code, 0);
  const Table e = read_table(dir + "/e-curves.csv"), s = read_table(dir + "/s.csv");
  for (const char* column : {"t", "m2", "ipr", "energy_error", "m2_centroid"})
    EXPECT_EQ(e.at(column), s.at(column)) << column;
  EXPECT_EQ(e.at("ic").front(), "mode");
  const auto spread = nlohmann::json::parse(read_file(dir + "/s.json"));
  EXPECT_EQ(number(read_table(dir + "/e.csv").at("gamma")[0]), spread["gamma"].get<double>());
  std::filesystem::remove_all(dir);
}

// Everything new at once (a k-type chain, a polydisperse one, a mode kick, the tangent map) is the
// same bytes for one and two threads.
TEST(ExponentsChains, ThreadCountInvariant) {
  const std::string dir = scratch_folder("exp-new-threads");
  const std::string args = study +
                           " --chains A --types 4.76e-3:0.5,3e-3:0.3,2e-3:0.2 --ic velocity,mode --mode 120 "
                           "--energy 1e-7 --mle --realizations 4";
  ASSERT_EQ(run_tool("exponents", args + " --threads 1 --output " + dir + "/t1").exit_code, 0);
  ASSERT_EQ(run_tool("exponents", args + " --threads 2 --output " + dir + "/t2").exit_code, 0);
  const std::string one = outputs(dir + "/t1");
  EXPECT_NE(one.find(",types,"), std::string::npos);
  EXPECT_EQ(one, outputs(dir + "/t2"));
  const std::string poly = study + " --chains none --polydisperse normal:3e-3:5e-4:2e-3 --ic velocity --realizations 4";
  ASSERT_EQ(run_tool("exponents", poly + " --threads 1 --output " + dir + "/p1").exit_code, 0);
  ASSERT_EQ(run_tool("exponents", poly + " --threads 2 --output " + dir + "/p2").exit_code, 0);
  EXPECT_NE(outputs(dir + "/p1").find(",polydisperse,"), std::string::npos);
  EXPECT_EQ(outputs(dir + "/p1"), outputs(dir + "/p2"));
  std::filesystem::remove_all(dir);
}

// correlations: two types as --types give the indicator's coefficient to rounding; three types
// drawn independently are uncorrelated beyond d = 0; any thread count gives the same bytes.
TEST(CorrelationsChains, MassCorrelationOfTypes) {
  const std::string dir = scratch_folder("corr-types");
  const std::string base = "--N 1000 --realizations 100 --max-distance 5 --quiet --output " + dir;
  for (const std::string kind : {"A", "RDM1", "RDM2"}) {
    ASSERT_EQ(run_tool("correlations", base + "/p.csv --disorder " + kind + " --q 0.3").exit_code, 0);
    ASSERT_EQ(run_tool("correlations", base + "/t.csv --disorder " + kind + " --types 4.76e-3:0.3,2e-3:0.7").exit_code,
              0);
    const Table p = read_table(dir + "/p.csv"), t = read_table(dir + "/t.csv");
    for (std::size_t d = 0; d <= 5; ++d) {
      EXPECT_NEAR(number(t.at("rho_mean")[d]), number(p.at("rho_mean")[d]), 1e-12) << kind << " d=" << d;
      EXPECT_EQ(t.at("rho_theory")[d], p.at("rho_theory")[d]) << kind << " d=" << d;
    }
    EXPECT_EQ(nlohmann::json::parse(read_file(dir + "/t.json"))["correlated"], "bead mass");
  }
  const std::string three = " --types 4.76e-3:0.5,3e-3:0.3,2e-3:0.2 --N 2000 --realizations 200 --max-distance 4";
  ASSERT_EQ(run_tool("correlations", "--quiet --threads 1 --output " + dir + "/k1.csv" + three).exit_code, 0);
  ASSERT_EQ(run_tool("correlations", "--quiet --threads 2 --output " + dir + "/k2.csv" + three).exit_code, 0);
  EXPECT_EQ(read_file(dir + "/k1.csv"), read_file(dir + "/k2.csv"));
  const Table k = read_table(dir + "/k1.csv");
  EXPECT_NEAR(number(k.at("rho_mean")[0]), 1, 1e-14);
  for (std::size_t d = 1; d <= 4; ++d) {  // 5 standard errors plus the O(1/N) bias of a finite ring
    EXPECT_NEAR(number(k.at("rho_mean")[d]), 0, 5 * number(k.at("rho_std")[d]) / std::sqrt(200.0) + 1e-3) << d;
    EXPECT_EQ(number(k.at("rho_theory")[d]), 0);
  }
  std::filesystem::remove_all(dir);
}

TEST(StudyChainsBadInput, OneLineExitTwoNoOutput) {
  const std::string dir = scratch_folder("chains-bad");
  const std::pair<const char*, const char*> cases[] = {
      {"exponents --mode 5", "--mode"},
      {"exponents --energy 1e-7", "--mode"},
      {"exponents --ic mode", "--mode"},
      {"exponents --ic mode --mode 500", "--mode"},
      {"exponents --ic mode --mode 5 --F0 10,0", "--F0"},
      {"exponents --chain-name mine", "--chain-name"},
      {"exponents --types-rule RDM1", "--types-rule"},
      {"exponents --types 4.76e-3:0.5,2e-3:0.5 --types-rule X", "--types-rule"},
      {"exponents --chains none", "--chains"},
      {"exponents --chains A,X", "--chains"},
      {"exponents --types 4.76e-3:1 --chain-name RDM1", "--chain-name"},
      {"exponents --types 4.76e-3:1 --chain-name a,b", "--chain-name"},
      {"exponents --types 4.76e-3:0.5", "--types"},
      {"exponents --polydisperse uniform:3e-3:2e-3", "--polydisperse"},
      {"exponents --deviation d.csv --mle", "--deviation"},
      {"correlations --types 4.76e-3:0.5,3e-3:0.6", "--types"},
      {"correlations --polydisperse normal:1e-3", "--polydisperse"},
      {"correlations --types 4.76e-3:1", "one kind of bead"},
      {"correlations --types 4.76e-3:0.5,3e-3:0.3,2e-3:0.2 --disorder RDM2", "RDM2"},
  };
  for (const auto& [command, names] : cases) {
    const std::string text(command);
    const std::string tool = text.substr(0, text.find(' '));
    const std::string out = dir + (tool == "exponents" ? "/out" : "/out.csv");
    const ToolResult r = run_tool(tool, text.substr(text.find(' ') + 1) + " --N 101 --quiet --output " + out);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << command << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << command << ": " << r.err;
    EXPECT_TRUE(std::filesystem::is_empty(dir)) << command;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular::testing
