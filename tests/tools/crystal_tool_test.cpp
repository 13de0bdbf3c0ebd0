// The `crystal` tool's contract: its options are crystal_parameters()'s rows, bad input is one
// line naming the option with exit code 2 and nothing written, the JSON is the case's description
// (its parameters parse back to the case), and SLEPc's nearest modes and spectrum slicing (also on
// two MPI ranks) are the dense solver's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "granular/crystal/crystal_case.hpp"
#include "granular/files/crystal_files.hpp"
#include "granular/parameter_json.hpp"
#include "granular/study/crystal_ipr_map.hpp"
#include "tool_runner.hpp"

namespace granular::testing {
namespace {

/// The freq_khz column of a crystal CSV.
std::vector<double> crystal_frequencies(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "mode,freq_khz,omega2,ipr");
  std::vector<double> f;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::string mode, freq;
    std::getline(cells, mode, ',');
    std::getline(cells, freq, ',');
    f.push_back(std::stod(freq));
  }
  return f;
}

TEST(CrystalTool, HelpListsEveryRowOfTheTable) {
  const std::string dir = scratch_folder("crystal-help");
  ASSERT_EQ(std::system(("'" + tool_path("crystal") + "' --help > " + dir + "/help.txt").c_str()), 0);
  const std::string help = read_file(dir + "/help.txt");
  for (const auto& p : crystal_parameters()) {
    std::string flag = "--" + front_end_word(p.name);
    std::replace(flag.begin(), flag.end(), '_', '-');
    EXPECT_NE(help.find(flag + " "), std::string::npos) << p.name;
  }
  std::filesystem::remove_all(dir);
}

TEST(CrystalTool, WritesTheModesAndACaseThatParsesBack) {
  const std::string dir = scratch_folder("crystal-run");
  const std::string args = "--lattice hexagonal --Lx 6 --Ly 6 --F0 5 --disorder mass --width 0.2 --seed 3 --vectors";
  const ToolResult r = run_tool("crystal", args + " --quiet --output " + dir + "/c");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto f = crystal_frequencies(dir + "/c.csv");
  EXPECT_EQ(f.size(), 72U);  // every mode: 2 per bead
  for (std::size_t k = 1; k < f.size(); ++k) EXPECT_LE(f[k - 1], f[k]);
  EXPECT_GT(f.front(), 0);  // rigid under its walls
  const auto meta = nlohmann::json::parse(read_file(dir + "/c.json"));
  const CrystalCase c = parse_rows(meta.at("parameters"), crystal_parameters());
  EXPECT_EQ(c.packing.lattice, Lattice::hexagonal);
  EXPECT_EQ(c.packing.precompression, 5.0);
  EXPECT_EQ(c.disorder.width, 0.2);
  EXPECT_EQ(c.disorder.seed, 3U);
  EXPECT_EQ(meta.at("spectrum").at("method"), "lapack");
  EXPECT_LE(meta.at("static_state").at("max_imbalance").get<double>(), 1e-12);
  // modes file: 72 modes × 36 beads, one header line
  std::ifstream modes(dir + "/c-modes.csv");
  std::size_t lines = 0;
  for (std::string line; std::getline(modes, line);) ++lines;
  EXPECT_EQ(lines, 1 + 72U * 36U);
  std::filesystem::remove_all(dir);
}

/// Every frequency of `some` is one of `all` to 1e-10 relative.
void expect_among(const std::vector<double>& some, const std::vector<double>& all, const std::string& what) {
  for (double f : some) {
    double closest = INFINITY;
    for (double g : all) closest = std::fmin(closest, std::fabs(f - g));
    EXPECT_LE(closest, 1e-10 * f) << what << ": " << f;
  }
}

TEST(CrystalTool, NearestModesByArpackAndSlepcAreTheDenseOnes) {
  const std::string dir = scratch_folder("crystal-near");
  const std::string args = "--lattice hexagonal --Lx 12 --Ly 12 --disorder mass --width 0.3 --quiet";
  ASSERT_EQ(run_tool("crystal", args + " --output " + dir + "/all").exit_code, 0);
  const auto all = crystal_frequencies(dir + "/all.csv");
  const std::string near = args + " --near " + std::to_string(all[all.size() / 2]) + " --count 10";
  for (const std::string method : {"arpack", "slepc"}) {
    const ToolResult r = run_tool("crystal", near + " --method " + method + " --output " + dir + "/" + method);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto some = crystal_frequencies(dir + "/" + method + ".csv");
    ASSERT_EQ(some.size(), 10U);
    expect_among(some, all, method);
  }
  // Spectrum slicing: every dense mode inside the window, none outside, each to 1e-10.
  const double lo = 0.5 * (all[100] + all[101]), hi = 0.5 * (all[130] + all[131]);
  const std::string window = args + " --window " + std::to_string(lo) + ":" + std::to_string(hi);
  const ToolResult sliced = run_tool("crystal", window + " --output " + dir + "/window");
  ASSERT_EQ(sliced.exit_code, 0) << sliced.err;
  const auto inside = crystal_frequencies(dir + "/window.csv");
  EXPECT_EQ(inside.size(), static_cast<std::size_t>(std::count_if(all.begin(), all.end(), [&](double f) {
              return f >= std::stod(std::to_string(lo)) && f <= std::stod(std::to_string(hi));
            })));
  expect_among(inside, all, "window");
#ifdef GRANULAR_MPIEXEC_PATH
  const std::string mpirun = "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " +
                             std::string(GRANULAR_MPIEXEC_PATH) + " --oversubscribe -np 2 ";
  const std::string command =
      mpirun + tool_path("crystal") + " " + near + " --method slepc --output " + dir + "/ranks > /dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const auto ranks = crystal_frequencies(dir + "/ranks.csv"), one = crystal_frequencies(dir + "/slepc.csv");
  ASSERT_EQ(ranks.size(), one.size());
  for (std::size_t k = 0; k < one.size(); ++k) EXPECT_NEAR(ranks[k], one[k], 1e-10 * one[k]);
  const std::string sliced_on_ranks =
      mpirun + tool_path("crystal") + " " + window + " --output " + dir + "/window-ranks > /dev/null 2>&1";
  ASSERT_EQ(std::system(sliced_on_ranks.c_str()), 0);
  const auto inside_ranks = crystal_frequencies(dir + "/window-ranks.csv");
  ASSERT_EQ(inside_ranks.size(), inside.size());
  for (std::size_t k = 0; k < inside.size(); ++k) EXPECT_NEAR(inside_ranks[k], inside[k], 1e-10 * inside[k]);
#endif
  std::filesystem::remove_all(dir);
}

TEST(CrystalTool, BadInputIsOneLineNamingTheOptionAndWritesNothing) {
  const std::string dir = scratch_folder("crystal-bad");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--Lx 1", "--Lx"},
      {"--lattice cubic", "--lattice"},
      {"--lattice hexagonal --Ly 5", "--Ly"},
      {"--F0 -1", "--F0"},
      {"--strain 0.01", "--strain"},                     // with walls: no effect, refused
      {"--boundary periodic --strain 0.2", "--strain"},  // out of range
      {"--width 1.5", "--width"},
      {"--disorder radius", "--disorder"},  // without --width
      {"--count 5", "--count"},             // without --near
      {"--method slepc", "--method"},       // without --near
      {"--near 20 --count 0", "--count"},
      {"--near -3", "--near"},
      {"--near 500", "--near 500 kHz: above"},  // a slip: every mode of the 8 x 8 default is below 18 kHz
      {"--window 5", "--window"},
      {"--window 3:1", "--window"},
      {"--near 10 --window 1:2", "--window"},
      {"--window 100:200", "--window from 100 kHz: above"},
      {"--window 0.001:0.002", "--window"},  // no mode in it (the lowest is near 1 kHz): SLEPc, so MPI, ran
      {"--ratio-lo 30 --ratio-hi 10", "--ratio-hi"},
      {"--boundary periodic --strain 0.01", "packing"},  // the compressed periodic square lattice is not rigid
  };
  for (const auto& [args, names] : cases) {
    const ToolResult r = run_tool("crystal", args + " --output " + dir + "/out");
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.csv")) << args;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.json")) << args;
  }
  std::filesystem::remove_all(dir);
}

// crystal-ipr-map: its CSV is the library's map (numbers in shortest round-trip form, so read
// back exactly), and the same bytes on 1 or 2 threads and on 2 MPI ranks.
TEST(CrystalIprMapTool, WritesTheLibrarysMapTheSameOnThreadsAndRanks) {
  const std::string dir = scratch_folder("crystal-map");
  const std::string args = "--lattice hexagonal --Lx 8 --Ly 8 --widths 0,0.6 --realizations 3 --bin-hz 3000 --quiet";
  ASSERT_EQ(run_tool("crystal-ipr-map", args + " --threads 1 --output " + dir + "/one").exit_code, 0);
  ASSERT_EQ(run_tool("crystal-ipr-map", args + " --threads 2 --output " + dir + "/two").exit_code, 0);
  const std::string csv = read_file(dir + "/one.csv");
  EXPECT_EQ(read_file(dir + "/two.csv"), csv);
  const auto meta = nlohmann::json::parse(read_file(dir + "/one.json"));
  const CrystalIprMapConfig c = parse_rows(meta.at("parameters"), crystal_ipr_map_parameters());
  EXPECT_EQ(c.widths, (std::vector<double>{0, 0.6}));
  std::ostringstream expected;
  write_crystal_ipr_map_csv(expected, c, crystal_ipr_map(c));
  EXPECT_EQ(csv, expected.str());
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "width,freq_lo_khz,freq_hi_khz,modes,ipr,ratio,ratios");
#ifdef GRANULAR_MPIEXEC_PATH
  const std::string command = "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " +
                              std::string(GRANULAR_MPIEXEC_PATH) + " --oversubscribe -np 2 " +
                              tool_path("crystal-ipr-map") + " " + args + " --threads 1 --output " + dir +
                              "/ranks > /dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_EQ(read_file(dir + "/ranks.csv"), csv);
  EXPECT_EQ(nlohmann::json::parse(read_file(dir + "/ranks.json")).at("ranks"), 2);
#endif
  EXPECT_FALSE(std::filesystem::exists(dir + "/one.checkpoint")) << "the checkpoint goes once the map is written";
  std::filesystem::remove_all(dir);
}

TEST(CrystalIprMapTool, BadInputIsOneLineNamingTheOptionAndWritesNothing) {
  const std::string dir = scratch_folder("crystal-map-bad");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--widths 1.2", "--widths"},         {"--realizations 0", "--realizations"},
      {"--bin-hz 0", "--bin-hz"},           {"--Lx 1", "--Lx"},
      {"--threads -2", "--threads"},        {"--resume --fresh", "--fresh"},
      {"--skip-failed", "--skip-failed"},   {"--near -1", "--near"},
      {"--near 10 --count 128", "--count"},  // 8 x 8 beads: 128 degrees of freedom
  };
  for (const auto& [args, names] : cases) {
    const ToolResult r = run_tool("crystal-ipr-map", args + " --output " + dir + "/out");
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.csv")) << args;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.json")) << args;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular::testing
