// localization end to end: the CSV/JSON contract, byte-identical output for any thread count,
// the same chain from --config/--radii files, node counts against the `spectrum` tool, and bad
// input rejected with exit code 2, one line naming the option and no output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "granular/model/disorder.hpp"
#include "granular/number_format.hpp"
#include "tool_runner.hpp"

namespace granular::testing {
namespace {

std::vector<std::vector<double>> read_csv(const std::string& path, std::string* header = nullptr) {
  std::istringstream in(read_file(path));
  std::string line;
  std::getline(in, line);
  if (header) *header = line;
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST(LocalizationTool, CsvAndJsonContractAndThreadIndependence) {
  const std::string dir = scratch_folder("loc-contract");
  const std::string job = "--disorder RDM1 --xi 0.5 --q 0.5 --F0 10 --f 0:50:0.5 --N 1e5 --quiet";
  ASSERT_EQ(run_tool("localization", job + " --seed 1 --threads 1 --output " + dir + "/t1").exit_code, 0);
  ASSERT_EQ(run_tool("localization", job + " --seed 1 --threads 2 --output " + dir + "/t2").exit_code, 0);
  ASSERT_EQ(run_tool("localization", job + " --seed 2 --output " + dir + "/s2").exit_code, 0);
  const std::string one = read_file(dir + "/t1.csv");
  EXPECT_EQ(one, read_file(dir + "/t2.csv"));
  EXPECT_NE(one, read_file(dir + "/s2.csv"));
  std::string header;
  const auto rows = read_csv(dir + "/t1.csv", &header);
  EXPECT_EQ(header, "freq_khz,lyapunov,lyapunov_err,loc_length,idos,dos,resolved");
  ASSERT_EQ(rows.size(), 101u);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto& r = rows[k];
    ASSERT_EQ(r.size(), 7u);
    EXPECT_TRUE(r[6] == 0 || r[6] == 1);
    EXPECT_DOUBLE_EQ(r[0], 0.5 * static_cast<double>(k));
    EXPECT_GE(r[2], 0);
    if (r[1] > 0) {
      EXPECT_DOUBLE_EQ(r[3], 1 / r[1]);
    }
    const double count = r[4] * 1e5;  // idos × N is a whole number of modes
    EXPECT_NEAR(count, std::round(count), 1e-6);
    if (k > 0) {
      EXPECT_GE(r[4], rows[k - 1][4]);
    }
  }
  EXPECT_EQ(rows.back()[4], 1.0);  // every mode of this chain lies below 50 kHz
  // dos differences the idos column
  EXPECT_DOUBLE_EQ(rows[10][5], (rows[11][4] - rows[9][4]) / 1.0);

  const auto meta = nlohmann::json::parse(read_file(dir + "/t1.json"));
  EXPECT_EQ(meta["tool"], "localization");
  EXPECT_EQ(meta["version"], GRANULAR_VERSION);
  EXPECT_NE(meta["command"].get<std::string>().find("--N 1e5"), std::string::npos);
  EXPECT_GT(meta["wall_time_s"].get<double>(), 0);
  EXPECT_EQ(meta["chain"]["disorder"], "RDM1");
  EXPECT_EQ(meta["chain"]["N"], 100000);
  EXPECT_EQ(meta["chain"]["seed"], 1);
  EXPECT_EQ(meta["chain"]["realization"], 0);
  EXPECT_EQ(meta["chain"]["xi"], 0.5);
  EXPECT_EQ(meta["chain"]["q"], 0.5);
  EXPECT_EQ(meta["chain"]["F0_N"], 10.0);
  EXPECT_EQ(meta["parameters"]["frequencies_khz"], "0:50:0.5");
  EXPECT_EQ(meta["parameters"]["frequency_count"], 101);
  EXPECT_EQ(meta["parameters"]["segments"], 32);
  EXPECT_EQ(meta["parameters"]["threads"], 1);
  EXPECT_NEAR(meta["band_edges_khz"]["fb1"].get<double>(), 11.9546, 1e-4);
  for (const char* column : {"freq_khz", "lyapunov", "lyapunov_err", "loc_length", "idos", "dos", "resolved"})
    EXPECT_TRUE(meta["columns"].contains(column)) << column;
  EXPECT_NE(meta["resolved_rule"].get<std::string>().find("10 ln(N)/N"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// ℓ is flagged a measurement only where the chain resolves it: not at f = 0 (λ = ln N / N, the
// finite-size floor) nor in the low decade up to 1 kHz (λ ∝ f², ℓ longer than a segment / 10), but deep in the
// band of an Anderson chain, where ℓ is a few hundred beads or less.
TEST(LocalizationTool, UnresolvedLengthsAreFlagged) {
  const std::string dir = scratch_folder("loc-resolved");
  ASSERT_EQ(run_tool("localization",
                     "--disorder A --xi 0.5 --q 0.5 --N 1e5 --f 0,0.3,0.5,1,15,20 --quiet --output " + dir + "/a")
                .exit_code,
            0);
  const auto rows = read_csv(dir + "/a.csv");
  ASSERT_EQ(rows.size(), 6u);
  const double floor = std::log(1e5) / 1e5;
  EXPECT_NEAR(rows[0][1], floor, 0.1 * floor);  // f = 0: linear growth, λ = ln N / N
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(rows[k][6], 0) << rows[k][0] << " kHz, loc_length " << rows[k][3];
    EXPECT_GT(rows[k][3], 1e5 / 32 / 10) << rows[k][0] << " kHz";  // the rule's reason: ℓ > segment / 10
  }
  for (std::size_t k = 4; k < 6; ++k) {
    EXPECT_EQ(rows[k][6], 1) << rows[k][0] << " kHz, loc_length " << rows[k][3];
    EXPECT_LT(rows[k][3], 300) << rows[k][0] << " kHz";
  }
  std::filesystem::remove_all(dir);
}

// One frequency: the DOS from node counts at f ± 0.005 kHz, not NaN; the same as a list with that step.
TEST(LocalizationTool, OneFrequencyHasADensityOfStates) {
  const std::string dir = scratch_folder("loc-one");
  const std::string chain = "--disorder A --xi 0.5 --q 0.5 --N 1e5 --quiet --output ";
  ASSERT_EQ(run_tool("localization", chain + dir + "/one --f 10").exit_code, 0);
  ASSERT_EQ(run_tool("localization", chain + dir + "/three --f 9.995,10,10.005").exit_code, 0);
  const auto one = read_csv(dir + "/one.csv"), three = read_csv(dir + "/three.csv");
  ASSERT_EQ(one.size(), 1u);
  ASSERT_TRUE(std::isfinite(one[0][5]));
  EXPECT_GT(one[0][5], 0);
  EXPECT_NEAR(one[0][5], three[1][5], 1e-9 * three[1][5]);
  std::filesystem::remove_all(dir);
}

TEST(LocalizationTool, FilesGiveTheSameChainAsTheRandomRealization) {
  // The realization written out as a types file and as a radii file is the same chain: same bytes.
  const std::string dir = scratch_folder("loc-files");
  const auto types = realization_configuration(Disorder::rdm2, 0.3, 5000, 4, 2);
  const auto radii = radii_of(types, 4.76e-3, 0.6);
  {
    std::ofstream t(dir + "/chain.types"), r(dir + "/chain.radii");
    t << "# realization 2 of seed 4\n";
    for (auto v : types) t << int(v) << "\n";
    for (double v : radii) r << format_number(v) << "\n";
  }
  const std::string common = " --f 1:40:1 --quiet --output ";  // (--xi is the radii file's own)
  ASSERT_EQ(run_tool("localization",
                     "--disorder RDM2 --q 0.3 --N 5000 --seed 4 --realization 2 --xi 0.6" + common + dir + "/random")
                .exit_code,
            0);
  ASSERT_EQ(run_tool("localization", "--config " + dir + "/chain.types --xi 0.6" + common + dir + "/types").exit_code,
            0);
  ASSERT_EQ(run_tool("localization", "--radii " + dir + "/chain.radii" + common + dir + "/radii").exit_code, 0);
  const std::string random = read_file(dir + "/random.csv");
  EXPECT_EQ(random, read_file(dir + "/types.csv"));
  EXPECT_EQ(random, read_file(dir + "/radii.csv"));
  EXPECT_EQ(run_tool("localization", "--config " GRANULAR_DATA_DIR
                                     "/examples/diatomic-10.types --xi 0.5 --f 1:40:1 --quiet --output " +
                                         dir + "/d")
                .exit_code,
            0);
  std::filesystem::remove_all(dir);
}

TEST(LocalizationTool, NodeCountsAreTheModesOfTheSpectrumTool) {
  const std::string dir = scratch_folder("loc-spectrum");
  const std::string chain = "--disorder A --xi 0.5 --q 0.4 --N 300 --seed 3 --realization 1";
  ASSERT_EQ(run_tool("spectrum", chain + " --output " + dir + "/s.csv").exit_code, 0);
  ASSERT_EQ(run_tool("localization", chain + " --f 0:60:0.05 --quiet --output " + dir + "/loc").exit_code, 0);
  std::vector<double> modes;
  for (const auto& row : read_csv(dir + "/s.csv")) modes.push_back(row[1]);
  int compared = 0;
  for (const auto& row : read_csv(dir + "/loc.csv")) {
    const double f = row[0];
    long below = 0;
    bool near = false;
    for (double m : modes) {
      below += m < f;
      near = near || std::fabs(m - f) < 1e-9 * f;
    }
    if (near) continue;
    EXPECT_EQ(std::lround(row[4] * 300), below) << f << " kHz";
    ++compared;
  }
  EXPECT_GT(compared, 1150);
  std::filesystem::remove_all(dir);
}

struct BadInput {
  std::string args, names;
};

TEST(LocalizationTool, BadInputExitsTwoWithOneLineAndNoOutput) {
  const std::string dir = scratch_folder("loc-bad");
  const std::vector<BadInput> cases = {
      {"--f 3,2", "--f"},
      {"--f -1:5", "--f"},
      {"--f 5:1", "--f"},
      {"--f abc", "--f"},
      {"--f nan", "--f"},
      {"--f 1:2:0", "--f"},
      {"--N 1", "--N"},
      {"--N 2.5", "--N"},
      {"--N 1e13", "--N"},
      {"--N abc", "--N"},
      {"--F0 0", "--F0"},
      {"--F0 -1", "--F0"},
      {"--xi 0", "--xi"},
      {"--q 2", "--q"},
      {"--disorder X", "--disorder"},
      {"--segments 1", "--segments"},
      {"--threads -1", "--threads"},
      {"--seed -1", "--seed"},
      {"--config /nonexistent/c.types", "/nonexistent/c.types"},
      {"--radii /nonexistent/r.radii", "/nonexistent/r.radii"},
      {"--config a --radii b", "--config"},
  };
  for (const BadInput& c : cases) {
    { std::ofstream(dir + "/old.csv") << "precious\n"; }
    for (const std::string out : {"/new", "/old"}) {
      std::string baseline;  // a quick valid run, for the options the case leaves alone
      const bool file = reads_chain_file(c.args);
      if (c.args.find("--N ") == std::string::npos && !file) baseline += " --N 1000";  // (a file sets N)
      if (c.args.find("--f ") == std::string::npos) baseline += " --f 1:2";
      const ToolResult r = run_tool("localization", c.args + baseline + " --output " + dir + out);
      EXPECT_EQ(r.exit_code, 2) << c.args << ": " << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << ": " << r.err;
      EXPECT_NE(r.err.find(c.names), std::string::npos) << c.args << ": " << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir + "/new.csv")) << c.args;
    EXPECT_FALSE(std::filesystem::exists(dir + "/new.json")) << c.args;
    EXPECT_FALSE(std::filesystem::exists(dir + "/old.json")) << c.args;
    EXPECT_EQ(read_file(dir + "/old.csv"), "precious\n") << c.args;
  }
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u) << "a temporary file was left behind";
  EXPECT_EQ(run_tool("localization", "--N 100 --f 1 --output /nonexistent-folder/x").exit_code, 1);
  EXPECT_EQ(run_tool("localization", "--help").exit_code, 0);
  EXPECT_EQ(run_tool("localization", "--version").exit_code, 0);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular::testing
