// Beyond the paper on the command line: `restitution`, and `spreading`'s damping and --mle options.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tool_runner.hpp"

namespace granular::testing {
namespace {

TEST(RestitutionTool, ElasticWithoutDampingAndBelowOneWithIt) {
  const std::string dir = scratch_folder("restitution");
  const ToolResult r =
      run_tool("restitution", "--impact-speed 0.01,0.1 --kk-gamma 0,1e-6 --quiet --output " + dir + "/e.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream csv(read_file(dir + "/e.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "impact_speed,kk_gamma,restitution,deficit_small_damping,contact_time,hertz_time");
  std::vector<double> e;
  while (std::getline(csv, line)) {
    std::stringstream row(line);
    std::string cell;
    for (int k = 0; k < 3; ++k) std::getline(row, cell, ',');
    e.push_back(std::stod(cell));
  }
  ASSERT_EQ(e.size(), 4u);
  EXPECT_NEAR(e[0], 1.0, 1e-9);
  EXPECT_NEAR(e[1], 1.0, 1e-9);
  EXPECT_LT(e[2], 1.0);
  EXPECT_LT(e[3], e[2]);  // faster impact, more loss
  EXPECT_TRUE(std::filesystem::exists(dir + "/e.json"));
  std::filesystem::remove_all(dir);
}

TEST(SpreadingTool, DampingAndMleColumns) {
  const std::string dir = scratch_folder("spreading-beyond");
  const std::string base = "--N 101 --F0 1 --T 2e-4 --fit 1e-4:2e-4 --samples 10 --quiet";
  ASSERT_EQ(run_tool("spreading", base + " --kk-gamma 1e-6 --output " + dir + "/d").exit_code, 0);
  std::string header = read_file(dir + "/d.csv");
  EXPECT_EQ(header.substr(0, header.find('\n')), "t,m2,ipr,energy_error,m2_centroid,dissipated");
  ASSERT_EQ(run_tool("spreading", base + " --mle --deviation " + dir + "/w.csv --output " + dir + "/m").exit_code, 0);
  header = read_file(dir + "/m.csv");
  EXPECT_EQ(header.substr(0, header.find('\n')), "t,m2,ipr,energy_error,m2_centroid,mle");
  header = read_file(dir + "/w.csv");
  EXPECT_EQ(header.substr(0, header.find('\n')), "t,site,share");
  std::filesystem::remove_all(dir);
}

// The Kuwabara-Kono force is not clipped at zero (docs/physics.md): every --kk-gamma help says that
// its contacts can pull, unlike the elastic contact's.
TEST(BeyondTools, KuwabaraKonoHelpSaysItsContactsCanPull) {
  const std::string out = std::filesystem::temp_directory_path() / ("granular-help-" + std::to_string(::getpid()));
  for (const char* tool : {"spreading", "restitution"}) {
    ASSERT_EQ(std::system(("'" + tool_path(tool) + "' --help >" + out).c_str()), 0) << tool;
    const std::string help = read_file(out);
    const auto at = help.find("--kk-gamma");
    ASSERT_NE(at, std::string::npos) << tool;
    const std::string entry = help.substr(at, help.find("\n  -", at + 1) - at);
    EXPECT_NE(entry.find("can pull"), std::string::npos) << tool << ": " << entry;
  }
  std::filesystem::remove(out);
}

TEST(BeyondTools, BadInputExitsTwoNamingTheFlagWithNoOutput) {
  const std::string dir = scratch_folder("beyond-bad");
  const std::pair<const char*, const char*> cases[] = {
      {"restitution --impact-speed 0", "--impact-speed"},
      {"restitution --kk-gamma -1", "--kk-gamma"},
      {"restitution --R1 -1", "--R1"},
      {"restitution --integrator euler", "integrator"},
      {"spreading --N 51 --kk-gamma -1", "--kk-gamma"},
      {"spreading --N 51 --damping-time nan", "--damping-time"},
      {"spreading --N 51 --mle --kk-gamma 1e-6", "--mle"},
      {"spreading --N 51 --mle --integrator reference", "--integrator"},
      {"spreading --N 51 --deviation x.csv", "--deviation"},
      {"spreading --N 51 --mle --renormalize 0", "--renormalize"},
  };
  for (const auto& [command, names] : cases) {
    const std::string text(command);
    const std::string tool = text.substr(0, text.find(' '));
    const ToolResult r = run_tool(tool, text.substr(text.find(' ') + 1) + " --output " + dir + "/out.csv");
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << command << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.csv")) << command;
  }
  EXPECT_EQ(run_tool("restitution", "--help").exit_code, 0);
  EXPECT_EQ(run_tool("restitution", "--version").exit_code, 0);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular::testing
