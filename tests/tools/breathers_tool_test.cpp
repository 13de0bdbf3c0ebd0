// breathers end to end: a short diatomic branch writes the CSV and JSON contract; bad input exits
// with the tools' codes (2 bad input, 3 numerical failure), one line naming the problem, and
// writes nothing.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <hdf5.h>
#include <nlohmann/json.hpp>

#include "granular/linear/band_edges.hpp"
#include "granular/model/named_chains.hpp"
#include "orbits/breather_fixtures.hpp"
#include "tool_runner.hpp"

namespace granular::testing {
namespace {

std::string diatomic_file(const std::string& dir, std::size_t n) {
  const std::string path = dir + "/diatomic.txt";
  std::ofstream out(path);
  for (std::size_t i = 0; i < n; ++i) out << (i % 2 == 0 ? 2 : 1) << '\n';  // light bead in the centre
  return path;
}

double optical_edge_khz() { return band_edges(steel, paper_r1, 0.5, 10).fb2 / 1e3; }

TEST(BreathersTool, ShortDiatomicBranchWritesCsvAndJson) {
  const std::string dir = scratch_folder("breathers-run");
  const std::string args = "--config " + diatomic_file(dir, 21) + " --xi 0.5 --near " +
                           std::to_string(optical_edge_khz()) + " --max-points 4 --quiet --output " + dir + "/b";
  const auto r = run_tool("breathers", args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream csv(read_file(dir + "/b.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line,
            "omega_rad_s,freq_khz,energy_J,amplitude_m,centre,max_multiplier,stable,complete,verdict_trusted,"
            "newton_iterations,residual,max_open_fraction");
  int rows = 0;
  double previous = 1e300;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::stringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) v.push_back(std::stod(f));
    ASSERT_EQ(v.size(), 12u);
    EXPECT_LT(v[1], previous);  // down from the optical edge
    EXPECT_NEAR(v[0], 2 * 3.141592653589793 * v[1] * 1e3, 1e-9 * v[0]);
    EXPECT_EQ(v[7], 1);                         // 21 beads: the dense method, every multiplier
    EXPECT_EQ(v[6], v[5] <= 1 + 1e-6 ? 1 : 0);  // the verdict is the column's max|mu| against the tolerance
    EXPECT_EQ(v[8], 1);                         // F0 > 0: a verdict of the orbit
    previous = v[1];
    ++rows;
  }
  EXPECT_EQ(rows, 4);
  const auto meta = nlohmann::json::parse(read_file(dir + "/b.json"));
  EXPECT_EQ(meta["points"].size(), 4u);
  EXPECT_FALSE(meta["continuation"]["stop_reason"].get<std::string>().empty());
  EXPECT_TRUE(meta["floquet"]["verdict_untrusted_reason"].is_null());             // F0 > 0: every verdict trusted
  const fixtures::Hdf5Verdicts h5 = fixtures::read_hdf5_verdicts(dir + "/b.h5");  // and so says the HDF5
  ASSERT_TRUE(h5.ok);
  EXPECT_EQ(h5.trusted, std::vector<std::uint64_t>(4, 1));
  EXPECT_EQ(h5.reason, "");
  EXPECT_EQ(meta["output"], dir + "/b.csv");
  std::filesystem::remove_all(dir);
}

// Pseudo-arclength from the tool, its HDF5 profiles, and a profile from there as a seed file: the
// seeded run starts on that point of the branch.
TEST(BreathersTool, ArclengthBranchProfilesSeedTheNextRun) {
  const std::string dir = scratch_folder("breathers-arc");
  const std::string chain = "--config " + diatomic_file(dir, 21) + " --xi 0.5 --quiet";
  auto r = run_tool_in(dir, "breathers",
                       chain + " --near " + std::to_string(optical_edge_khz()) +
                           " --max-points 4 --continuation arclength --output arc");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto meta = nlohmann::json::parse(read_file(dir + "/arc.json"));
  EXPECT_TRUE(meta["continuation"]["method"].get<std::string>().starts_with("pseudo-arclength"));
  EXPECT_EQ(meta["profiles"], "arc.h5");
  const hid_t file = H5Fopen((dir + "/arc.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  std::vector<double> x0(4 * 21), freq(4);
  for (const auto& [name, data] : {std::pair{"x0", &x0}, std::pair{"freq_khz", &freq}}) {
    const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
    ASSERT_GE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data->data()), 0) << name;
    H5Dclose(set);
  }
  H5Fclose(file);
  {
    std::ofstream seed(dir + "/seed.txt");
    seed << "# the last point's profile [m]\n" << std::setprecision(17);
    for (std::size_t i = 0; i < 21; ++i) seed << x0[3 * 21 + i] << '\n';
  }
  std::ostringstream start;
  start << std::setprecision(17) << freq[3];
  r = run_tool_in(dir, "breathers",
                  chain + " --seed-file seed.txt --start-khz " + start.str() + " --max-points 2 --output seeded");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream csv(read_file(dir + "/seeded.csv"));
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_EQ(std::stod(first.substr(first.find(',') + 1)), freq[3]);
  const auto seeded = nlohmann::json::parse(read_file(dir + "/seeded.json"));
  EXPECT_EQ(seeded["seed"]["profile"], "given");
  EXPECT_LE(seeded["points"][0]["newton_residuals"].back().get<double>(), 1e-10);
  EXPECT_LE(seeded["points"][0]["newton_residuals"].size(), 2u);  // it started on the orbit
  std::filesystem::remove_all(dir);
}

// F0 = 0 on on-site springs (a Newton's cradle held by springs of 1e7 N/m): the branch starts
// above the on-site frequency and goes up (hardening); every point converged.
TEST(BreathersTool, OnsiteSpringChainAtZeroPrecompression) {
  const std::string dir = scratch_folder("breathers-cradle");
  const auto r = run_tool("breathers",
                          "--quasi s1 --modulation 0 --phase 0 --k0-n-per-m 1e7 --F0 0 --N 21 "
                          "--start-offset 1e-2 --max-points 3 --quiet --output " +
                              dir + "/c");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto meta = nlohmann::json::parse(read_file(dir + "/c.json"));
  EXPECT_EQ(meta["seed"]["site"], 11);
  const double onsite = meta["seed"]["onsite_khz"].get<double>();
  ASSERT_EQ(meta["points"].size(), 3u);
  // The Floquet verdicts at F0 = 0 are the discretized map's (issue 42, item 5): untrusted, saying why.
  EXPECT_NE(meta["floquet"]["verdict_untrusted_reason"].get<std::string>().find("F0 = 0"), std::string::npos);
  std::ifstream csv(dir + "/c.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_NE(line.find(",stable,complete,verdict_trusted,newton_iterations,"), std::string::npos) << line;
  for (int row = 0; row < 3; ++row) {
    ASSERT_TRUE(std::getline(csv, line));
    std::vector<std::string> v;
    std::stringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) v.push_back(f);
    ASSERT_EQ(v.size(), 12u);
    EXPECT_EQ(v[8], "0") << line;
  }
  const fixtures::Hdf5Verdicts h5 = fixtures::read_hdf5_verdicts(dir + "/c.h5");  // the HDF5 says so too
  ASSERT_TRUE(h5.ok);
  EXPECT_EQ(h5.trusted, std::vector<std::uint64_t>(3, 0));
  EXPECT_EQ(h5.reason, meta["floquet"]["verdict_untrusted_reason"].get<std::string>());
  double previous = onsite;
  for (const auto& p : meta["points"]) {
    EXPECT_FALSE(p["verdict_trusted"].get<bool>());
    EXPECT_GT(p["freq_khz"].get<double>(), previous);
    EXPECT_LE(p["newton_residuals"].back().get<double>(), 1e-10);
    previous = p["freq_khz"].get<double>();
  }
  std::filesystem::remove_all(dir);
}

TEST(BreathersTool, BadInputExitsWithOneLineAndWritesNothing) {
  const std::string dir = scratch_folder("breathers-bad");
  const std::string config = diatomic_file(dir, 21);
  struct Case {
    std::string args, names;
    int code;
  };
  const Case cases[] = {
      {"--config " + config + " --xi 0.5 --start-khz " + std::to_string(0.3 * optical_edge_khz()), "--start-khz", 2},
      {"--N 2000 --mode 3 --newton dense", "--N", 2},
      {"--N 2000 --mode 3 --continuation arclength --newton dense", "--N", 2},
      {"--config " + config + " --xi 0.5 --mode 3 --newton gmres", "--newton", 2},
      {"--config " + config + " --xi 0.5 --mode 3 --floquet lapack", "--floquet", 2},
      {"--config " + config + " --xi 0.5 --mode 3 --floquet arpack --multipliers 40", "--multipliers", 2},
      {"--config " + config + " --xi 0.5 --mode 0", "--mode", 2},
      {"--config " + config + " --xi 0.5 --law linear --mode 3", "--law", 2},
      {"--config " + config + " --xi 0.5 --mode 3 --continuation pseudo", "--continuation", 2},
      // F0 = 0: refused without on-site springs; with them, no mode seeds and the start above the spring's.
      {"--config " + config + " --xi 0.5 --F0 0 --mode 3", "--F0", 2},
      {"--quasi s1 --F0 0 --N 21", "--F0", 2},  // S1's k0 in units of K, which is 0 at F0 = 0
      {"--quasi s1 --k0-n-per-m 1e7 --F0 0 --N 21 --mode 3", "--mode", 2},
      {"--quasi s1 --k0-n-per-m 1e7 --F0 0 --N 21 --site 22", "--site", 2},
      {"--quasi s1 --k0-n-per-m 1e7 --F0 0 --N 21 --start-khz 1", "--start-khz", 2},
      {"--config " + config + " --xi 0.5 --mode 3 --site 2", "--site", 2},
      // Tolerances: finite and > 0 (zero once ran Newton to its iteration limit, or called every orbit unstable).
      {"--config " + config + " --xi 0.5 --mode 3 --tolerance 0", "--tolerance", 2},
      {"--config " + config + " --xi 0.5 --mode 3 --tolerance -1e-10", "--tolerance", 2},
      {"--config " + config + " --xi 0.5 --mode 3 --tolerance nan", "--tolerance", 2},
      {"--config " + config + " --xi 0.5 --mode 3 --stability-tolerance 0", "--stability-tolerance", 2},
      {"--config " + config + " --xi 0.5 --mode 3 --stability-tolerance -1e-6", "--stability-tolerance", 2},
      {"--config " + config + " --xi 0.5 --mode 3 --stability-tolerance inf", "--stability-tolerance", 2},
      {"--config " + config + " --xi 0.5 --seed-file " + dir + "/missing.txt --start-khz 30", "--seed-file", 2},
      {"--config " + config + " --xi 0.5 --seed-file " + config + " --start-khz 30 --mode 3", "--seed-file", 2},
      // Newton cannot reach a residual below rounding: a numerical failure.
      {"--config " + config + " --xi 0.5 --near " + std::to_string(optical_edge_khz()) + " --tolerance 1e-30", "Newton",
       3},
  };
  for (const auto& c : cases) {
    const auto r = run_tool_in(dir, "breathers", c.args + " --output out");
    EXPECT_EQ(r.exit_code, c.code) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.csv"));
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.json"));
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.h5"));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular::testing
