// The `klein-gordon` tool's contract: its options are klein_gordon_parameters()'s rows, its CSV is
// the library's run (one realization) or ensemble means printed at full precision, the same on
// one thread and on two, its JSON parses back to the case and replays it (--case), and bad input
// is one line naming the option with exit code 2 and nothing written.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "granular/analysis/power_law_fit.hpp"
#include "granular/klein_gordon/klein_gordon_case.hpp"
#include "granular/klein_gordon/klein_gordon_exponents.hpp"
#include "granular/klein_gordon/klein_gordon_run.hpp"
#include "granular/parameter_json.hpp"
#include "tool_runner.hpp"

namespace granular::testing {
namespace {

/// The columns of a klein-gordon CSV by header name, each cell read back exactly (shortest round trip).
std::map<std::string, std::vector<double>> kg_columns(const std::string& path) {
  std::ifstream in(path);
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::istringstream header(line); std::getline(header, cell, ',');) names.push_back(cell);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    for (const std::string& name : names) {
      std::getline(cells, cell, ',');
      columns[name].push_back(std::strtod(cell.c_str(), nullptr));
    }
  }
  return columns;
}

/// Equal bit for bit, NaN (log10 of Λ ≤ 0) equal to NaN.
void expect_same(const std::vector<double>& a, const std::vector<double>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!(std::isnan(a[k]) && std::isnan(b[k]))) {
      EXPECT_EQ(a[k], b[k]) << what << " at sample " << k;
    }
}

KleinGordonCase kg_tool_case(const std::string& dir, const std::string& prefix) {
  const auto meta = nlohmann::json::parse(read_file(dir + "/" + prefix + ".json"));
  return parse_rows(meta.at("parameters"), klein_gordon_parameters());
}

TEST(KleinGordonTool, HelpListsEveryRowOfTheTable) {
  const std::string dir = scratch_folder("kg-help");
  ASSERT_EQ(std::system(("'" + tool_path("klein-gordon") + "' --help > " + dir + "/help.txt").c_str()), 0);
  const std::string help = read_file(dir + "/help.txt");
  for (const auto& p : klein_gordon_parameters()) {
    std::string flag = "--" + front_end_word(p.name);
    std::replace(flag.begin(), flag.end(), '_', '-');
    EXPECT_NE(help.find(flag + " "), std::string::npos) << p.name;
  }
  std::filesystem::remove_all(dir);
}

TEST(KleinGordonTool, SingleSiteRunIsTheLibrarysRunAndItsJsonParsesBack) {
  const std::string dir = scratch_folder("kg-single");
  const ToolResult r =
      run_tool("klein-gordon",
               "--N 128 --W 3 --seed 5 --energy 0.4 --T 500 --samples 12 --quiet --output " + dir + "/a");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const KleinGordonCase c = kg_tool_case(dir, "a");
  EXPECT_EQ(c.run.chain.N, 128U);
  EXPECT_EQ(c.run.chain.W, 3.0);
  EXPECT_EQ(c.run.chain.seed, 5U);
  EXPECT_EQ(c.duration, 500.0);
  EXPECT_EQ(c.samples, 12);
  const KleinGordonRun run = run_klein_gordon(run_config(c), 0);
  auto csv = kg_columns(dir + "/a.csv");
  expect_same(csv["t"], run.time, "t");
  expect_same(csv["m2"], run.m2, "m2");
  expect_same(csv["P"], run.participation, "P");
  expect_same(csv["mle"], run.mle, "mle");
  const auto meta = nlohmann::json::parse(read_file(dir + "/a.json"));
  EXPECT_EQ(meta.at("max_energy_error").get<double>(), run.max_energy_error);
  EXPECT_LT(run.max_energy_error, 1e-4);
  EXPECT_EQ(meta.at("samples").at("count").get<std::size_t>(), run.time.size());
  std::filesystem::remove_all(dir);
}

TEST(KleinGordonTool, EnsembleIsTheLibrarysOnOneAndTwoThreadsAndReplays) {
  const std::string dir = scratch_folder("kg-ensemble");
  const std::string args = "--N 64 --block 21 --energy 0.1 --seed 7 --T 400 --samples 15 --realizations 4 --quiet";
  ASSERT_EQ(run_tool("klein-gordon", args + " --threads 1 --output " + dir + "/one").exit_code, 0);
  ASSERT_EQ(run_tool("klein-gordon", args + " --threads 2 --output " + dir + "/two").exit_code, 0);
  const std::string one = read_file(dir + "/one.csv");
  EXPECT_EQ(one, read_file(dir + "/two.csv"));  // byte for byte
  const KleinGordonCase c = kg_tool_case(dir, "one");
  const KleinGordonEnsemble e = klein_gordon_ensemble(run_config(c), c.realizations, 1);
  auto csv = kg_columns(dir + "/one.csv");
  expect_same(csv["t"], e.time, "t");
  expect_same(csv["m2"], e.m2, "m2");
  expect_same(csv["P"], e.participation, "P");
  expect_same(csv["mle"], e.mle, "mle");
  expect_same(csv["mean_log10_mle"], e.mean_log10_mle, "mean_log10_mle");
  // The run's JSON replays it.
  const ToolResult replay = run_tool("klein-gordon", "--case " + dir + "/one.json --quiet --output " + dir + "/again");
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  EXPECT_EQ(read_file(dir + "/again.csv"), one);
  std::filesystem::remove_all(dir);
}

TEST(KleinGordonTool, FitExponentsAreTheSlopesOfTheCsvsColumnsAndReplay) {
  const std::string dir = scratch_folder("kg-fit");
  const ToolResult r = run_tool("klein-gordon",
                                "--N 64 --block 21 --energy 0.1 --seed 7 --T 400 --samples 30 --realizations 3 "
                                "--threads 2 --fit 10:400 --output " +
                                    dir + "/a");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("alpha = "), std::string::npos) << r.err;
  const auto meta = nlohmann::json::parse(read_file(dir + "/a.json"));
  const nlohmann::json& x = meta.at("exponents");
  EXPECT_EQ(x.at("fit"), nlohmann::json({10.0, 400.0}));
  EXPECT_EQ(meta.at("parameters").at("fit"), x.at("fit"));
  auto csv = kg_columns(dir + "/a.csv");
  const double alpha = x.at("alpha").get<double>(), alpha_p = x.at("alpha_P").get<double>();
  EXPECT_EQ(alpha, loglog_slope(csv["t"], csv["m2"], 10, 400));
  EXPECT_EQ(alpha_p, loglog_slope(csv["t"], csv["P"], 10, 400));
  EXPECT_EQ(x.at("alpha_Lambda").get<double>(), log_time_slope(csv["t"], csv["mean_log10_mle"], 10, 400));
  EXPECT_EQ(x.at("samples").get<std::size_t>(), samples_inside(csv["t"], 10, 400));
  std::printf("  alpha = %.4f, alpha_P = %.4f, alpha_Lambda = %.4f on [10, 400]\n", alpha, alpha_p,
              x.at("alpha_Lambda").get<double>());
  // The realizations' slopes: the library's from the same case.
  const KleinGordonCase c = kg_tool_case(dir, "a");
  const KleinGordonExponents lib = klein_gordon_exponents(klein_gordon_ensemble(run_config(c), 3, 1), 10, 400);
  EXPECT_EQ(x.at("alpha_mean").get<double>(), lib.alpha.mean);
  EXPECT_EQ(x.at("alpha_error").get<double>(), lib.alpha.error);
  EXPECT_EQ(x.at("alpha_P_mean").get<double>(), lib.alpha_P.mean);
  EXPECT_EQ(x.at("alpha_Lambda_error").get<double>(), lib.alpha_Lambda.error);
  // The window is a parameter: --case replays it.
  const ToolResult replay = run_tool("klein-gordon", "--case " + dir + "/a.json --quiet --output " + dir + "/b");
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  EXPECT_EQ(nlohmann::json::parse(read_file(dir + "/b.json")).at("exponents"), x);
  // Without --fit, no exponents.
  ASSERT_EQ(run_tool("klein-gordon", "--N 32 --T 20 --samples 4 --quiet --output " + dir + "/c").exit_code, 0);
  EXPECT_FALSE(nlohmann::json::parse(read_file(dir + "/c.json")).contains("exponents"));
  std::filesystem::remove_all(dir);
}

/// A dataset of an HDF5 file, whole (empty if absent).
std::vector<double> kg_dataset(const std::string& file, const char* name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return {};
  std::vector<double> data;
  if (H5Lexists(f, name, H5P_DEFAULT) > 0) {
    const hid_t set = H5Dopen2(f, name, H5P_DEFAULT);
    const hid_t space = H5Dget_space(set);
    data.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
    if (H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0) data.clear();
    H5Sclose(space);
    H5Dclose(set);
  }
  H5Fclose(f);
  return data;
}

TEST(KleinGordonTool, EnergyMapIsTheLibrarysRealizationZeroInTheSpreadingLayout) {
  const std::string dir = scratch_folder("kg-map");
  const ToolResult r = run_tool("klein-gordon",
                                "--N 64 --block 21 --energy 0.1 --seed 7 --T 400 --samples 15 --realizations 2 "
                                "--energy-map --quiet --output " +
                                    dir + "/a");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const KleinGordonCase c = kg_tool_case(dir, "a");
  EXPECT_TRUE(c.run.energy_map);
  const KleinGordonRun run = run_klein_gordon(run_config(c), 0);
  const std::string map = dir + "/a-energy.h5";
  EXPECT_EQ(kg_dataset(map, "energy"), run.energy_map);  // bit for bit
  EXPECT_EQ(kg_dataset(map, "t"), run.time);
  const std::vector<double> site = kg_dataset(map, "site");
  ASSERT_EQ(site.size(), 64U);
  EXPECT_EQ(site.front(), 1.0);
  EXPECT_EQ(site.back(), 64.0);
  EXPECT_EQ(nlohmann::json::parse(read_file(dir + "/a.json")).at("energy_map_file").get<std::string>(), map);
  // Without --energy-map, no file.
  ASSERT_EQ(run_tool("klein-gordon", "--N 32 --T 20 --samples 4 --quiet --output " + dir + "/b").exit_code, 0);
  EXPECT_FALSE(std::filesystem::exists(dir + "/b-energy.h5"));
  std::filesystem::remove_all(dir);
}

TEST(KleinGordonTool, WithoutMleThereAreNoLambdaColumns) {
  const std::string dir = scratch_folder("kg-nomle");
  ASSERT_EQ(run_tool("klein-gordon", "--N 32 --T 20 --samples 4 --mle=false --quiet --output " + dir + "/a").exit_code,
            0);
  const std::string csv = read_file(dir + "/a.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "t,m2,P");
  std::filesystem::remove_all(dir);
}

TEST(KleinGordonTool, BadInputIsOneLineNamingTheOptionAndWritesNothing) {
  const std::string dir = scratch_folder("kg-bad");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--N 1", "--N"},
      {"--N -5", "--N"},
      {"--W 0", "--W"},
      {"--W nan", "--W"},
      {"--energy 0", "--energy"},
      {"--N 64 --block 65", "--block"},
      {"--dt 0", "--dt"},
      {"--dt inf", "--dt"},
      {"--T 0.1", "--T"},  // below one step
      {"--T 1e14", "--T"},
      {"--samples 0", "--samples"},
      {"--realizations 0", "--realizations"},
      {"--realizations 1e20", "--realizations"},
      {"--N 1e9", "--N"},
      {"--threads -1", "--threads"},
      {"--fit 0:100", "--fit"},
      {"--fit 100:10", "--fit"},
      {"--fit 100:2e4", "--fit"},  // past T = 1e4
      {"--fit 100:110", "--fit"},  // no sample inside
      {"--fit 100", "--fit"},
      {"--fit a:b", "--fit"},
      {"--energy-map --N 1e7 --samples 100", "--energy-map"},  // about 8.5e8 values
      {"--bogus 3", "bogus"},
      {"--case " + dir + "/none.json", "--case"},
      {"--case " + dir + "/none.json --N 10", "--case"},  // the file's case or the flags, not both
  };
  for (const auto& [args, names] : cases) {
    const ToolResult r = run_tool("klein-gordon", args + " --output " + dir + "/out");
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.csv")) << args;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.json")) << args;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out-energy.h5")) << args;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular::testing
