// --walls flat | sphere from the command line: sphere walls make a homogeneous chain the textbook
// fixed-end lattice, whose frequency ratios f_j / f_N = sin(jπ/2(N+1)) / sin(Nπ/2(N+1)) need no
// material constant; spectrum and ipr-map give them, and say which walls they used.
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tool_runner.hpp"

namespace granular::testing {
namespace {

// Column `column` (0-based) of a CSV with a header line.
std::vector<double> column_of(const std::string& path, std::size_t column) {
  std::istringstream in(read_file(path));
  std::string line, cell;
  std::getline(in, line);
  std::vector<double> values;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    for (std::size_t i = 0; i <= column; ++i) std::getline(row, cell, ',');
    values.push_back(std::stod(cell));
  }
  return values;
}

double lattice_ratio(std::size_t j, std::size_t n) {
  const double k = std::numbers::pi / (2.0 * static_cast<double>(n + 1));
  return std::sin(static_cast<double>(j) * k) / std::sin(static_cast<double>(n) * k);
}

TEST(WallsTool, SphereWallsGiveTheTextbookLatticeInSpectrumAndIprMap) {
  const std::string dir = scratch_folder("walls");
  const std::size_t n = 60;
  const std::string chain = "--disorder h --N " + std::to_string(n) + " --walls sphere";
  ASSERT_EQ(run_tool("spectrum", chain + " --output " + dir + "/s").exit_code, 0);
  ASSERT_EQ(run_tool("ipr-map", chain + " --q 1 --xi 1 --realizations 1 --quiet --output " + dir + "/m").exit_code, 0);
  const std::vector<double> spectrum = column_of(dir + "/s.csv", 1);
  const std::vector<double> map = column_of(dir + "/m.csv", 4);  // disorder,q,xi,mode,freq_khz,ipr
  ASSERT_EQ(spectrum.size(), n);
  ASSERT_EQ(map.size(), n);
  for (std::size_t j = 1; j <= n; ++j) {
    EXPECT_NEAR(spectrum[j - 1] / spectrum[n - 1], lattice_ratio(j, n), 1e-12) << "mode " << j;
    EXPECT_NEAR(map[j - 1], spectrum[j - 1], 1e-12 * spectrum[j - 1]) << "mode " << j;
  }
  const auto json = nlohmann::json::parse(read_file(dir + "/s.json"));
  EXPECT_EQ(json["chain"]["walls"], "fixed spheres, same radius and material as the end beads");
  EXPECT_EQ(nlohmann::json::parse(read_file(dir + "/m.json"))["parameters"]["walls"], json["chain"]["walls"]);

  // The default (flat) walls stiffen the end bonds: mode 1 moves off the lattice's ratio.
  ASSERT_EQ(run_tool("spectrum", "--disorder h --N " + std::to_string(n) + " --output " + dir + "/f").exit_code, 0);
  const std::vector<double> flat = column_of(dir + "/f.csv", 1);
  EXPECT_GT(flat[0] / flat[n - 1] / lattice_ratio(1, n) - 1, 1e-3);
}

}  // namespace
}  // namespace granular::testing
