// The butterfly tool (tools/butterfly.cpp): its files, their agreement with the spectrum tool on one
// ratio, and thread-count invariance.
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

}  // namespace
}  // namespace granular::testing
