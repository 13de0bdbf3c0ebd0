// The butterfly tool (tools/butterfly.cpp): its files, their agreement with the spectrum tool on one
// ratio, and thread-count invariance; --from dynamics, its peaks on the eigen mode's frequencies.
#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tool_runner.hpp"

namespace granular::testing {
namespace {

std::vector<std::vector<std::string>> csv_rows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

TEST(ButterflyTool, WritesEveryModeOfEveryRatioAsTheSpectrumToolDoes) {
  const std::string dir = scratch_folder("butterfly");
  const std::string chain = "--quasi s2 --modulation 0.4 --N 40 --seed 3 --realization 2";
  const ToolResult b = run_tool("butterfly", chain + " --ratios 0.2,0.382 --threads 2 --quiet --output " + dir + "/b");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const auto rows = csv_rows(dir + "/b.csv");
  ASSERT_EQ(rows.size(), 1u + 2 * 40);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"ratio", "mode", "freq_khz", "ipr"}));
  const ToolResult s = run_tool("spectrum", chain + " --ratio 0.382 --method fast --output " + dir + "/s.csv");
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto spectrum = csv_rows(dir + "/s.csv");
  ASSERT_EQ(spectrum.size(), 41u);
  const auto column = [](const auto& header, const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t f = column(spectrum[0], "freq_khz"), p = column(spectrum[0], "ipr");
  for (std::size_t k = 1; k <= 40; ++k) {
    EXPECT_EQ(rows[40 + k][2], spectrum[k][f]) << k;
    EXPECT_EQ(rows[40 + k][3], spectrum[k][p]) << k;
  }
  std::ifstream json(dir + "/b.json");
  const auto meta = nlohmann::json::parse(json);
  EXPECT_EQ(meta["box_counting"]["dimension"].size(), 2u);
  EXPECT_EQ(meta["chain"]["quasiperiodic"]["kind"], "s2");
  // One thread gives the same file.
  const ToolResult one =
      run_tool("butterfly", chain + " --ratios 0.2,0.382 --threads 1 --quiet --output " + dir + "/one");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(read_file(dir + "/one.csv"), read_file(dir + "/b.csv"));
  std::filesystem::remove_all(dir);
}

TEST(ButterflyTool, FromDynamicsPeaksOnTheEigenModeFrequenciesAndThreadInvariant) {
  const std::string dir = scratch_folder("butterfly-dyn");
  const std::string chain = "--quasi cylinders --modulation 0.3 --N 10 --phase 0.4 --ratios 0.3,0.5";
  const std::string run = " --from dynamics --T 4e-3 --spectrum-samples 801 --quiet";
  const ToolResult d = run_tool("butterfly", chain + run + " --threads 2 --output " + dir + "/d");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const auto rows = csv_rows(dir + "/d.csv");
  ASSERT_EQ(rows.size(), 1u + 2 * 401);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"ratio", "freq_khz", "power"}));
  std::ifstream json(dir + "/d.json");
  const auto meta = nlohmann::json::parse(json);
  EXPECT_EQ(meta["from"], "dynamics");
  EXPECT_EQ(meta["spectrum"]["of"], "velocity");
  const double resolution = meta["spectrum"]["resolution_khz"].get<double>();
  EXPECT_NEAR(resolution, 0.25, 0.001);
  // Each ratio's strongest peak is within 1/T of a frequency of the eigen mode's CSV.
  const ToolResult e = run_tool("butterfly", chain + " --quiet --output " + dir + "/e");
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const auto modes = csv_rows(dir + "/e.csv");
  for (const std::string ratio : {"0.3", "0.5"}) {
    double best = -1, at = 0;
    for (std::size_t i = 1; i < rows.size(); ++i)
      if (rows[i][0] == ratio && std::stod(rows[i][2]) > best) best = std::stod(rows[i][2]), at = std::stod(rows[i][1]);
    double nearest = 1e300;
    for (std::size_t i = 1; i < modes.size(); ++i)
      if (modes[i][0] == ratio) nearest = std::min(nearest, std::abs(std::stod(modes[i][2]) - at));
    EXPECT_EQ(best, 1.0) << ratio;
    EXPECT_LE(nearest, 1 / 4e-3 / 1e3) << "ratio " << ratio << ": strongest peak at " << at << " kHz";
  }
  const ToolResult one = run_tool("butterfly", chain + run + " --threads 1 --output " + dir + "/one");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(read_file(dir + "/one.csv"), read_file(dir + "/d.csv"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular::testing
