// Every tool's bad input: exit code 2, one line naming the option, and no output file
// created or truncated (DESIGN.md, command-line contracts).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tool_runner.hpp"

namespace granular::testing {
namespace {

struct BadInput {
  const char* tool;
  const char* args;
  const char* names;  ///< what the message must mention
};

std::ostream& operator<<(std::ostream& os, const BadInput& b) { return os << b.tool << " " << b.args; }

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, ExitsTwoWithOneLineAndNoOutput) {
  const BadInput& b = GetParam();
  const std::string dir = scratch_folder("bad");
  const std::string fresh = dir + "/fresh.csv", existing = dir + "/existing.csv";
  { std::ofstream(existing) << "precious\n"; }
  for (const std::string& out : {fresh, existing}) {
    const ToolResult r = run_tool(b.tool, std::string(b.args) + " --output " + out);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(b.names), std::string::npos) << "message does not name " << b.names << ": " << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(fresh));
  EXPECT_FALSE(std::filesystem::exists(dir + "/fresh.json"));
  EXPECT_EQ(read_file(existing), "precious\n");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u) << "a temporary file was left behind";
  std::filesystem::remove_all(dir);
}

const BadInput cases[] = {
    {"ipr-map", "--disorder X", "--disorder"},
    {"ipr-map", "--q 1.5", "--q"},
    {"ipr-map", "--q -0.1,0.5", "--q"},
    {"ipr-map", "--xi 0", "--xi"},
    {"ipr-map", "--xi 0.5:1.2", "--xi"},
    {"ipr-map", "--xi 1:0.5", "--xi"},
    {"ipr-map", "--xi abc", "--xi"},
    {"ipr-map", "--xi nan", "--xi"},
    {"ipr-map", "--N 1", "--N"},
    {"ipr-map", "--N -5", "--N"},
    {"ipr-map", "--N ten", "--N"},
    {"ipr-map", "--F0 -1", "--F0"},
    {"ipr-map", "--F0 0", "--F0"},
    {"ipr-map", "--F0 nan", "--F0"},
    {"ipr-map", "--F0 inf", "--F0"},
    {"ipr-map", "--realizations 0", "--realizations"},
    {"ipr-map", "--threads -1", "--threads"},
    {"ipr-map", "--solver magic", "--solver"},
    {"ipr-map", "--bogus 3", "bogus"},
    {"ipr-map", "--walls round", "--walls"},
    {"spectrum", "--walls round", "--walls"},
    {"spectrum", "--config /nonexistent/chain.types",
     "--config '/nonexistent/chain.types': cannot read the file (No such file or directory)"},
    {"localization", "--radii /nonexistent/radii.txt", "--radii"},
    {"localization", "--walls sphere --N 1e9", "--N"},
    {"spreading", "--walls none", "--walls"},
    {"spreading", "--site -1", "--site -1: must be >= 0"},  // not wrapped to 2^64 - 1 in an unsigned field
    {"spreading", "--samples -5", "--samples -5: must be >= 0"},
    {"spreading", "--bootstrap-seed -1", "--bootstrap-seed -1: must be >= 0"},
    {"exponents", "--renormalize -2 --mle", "--renormalize -2: must be >= 0"},
    {"exponents", "--walls none", "--walls"},
    // A --dt past the stability limit is named as such, not as the --fit-step (1e-5 s) judged on it.
    {"spreading", "--dt 1e-4", "--dt 1e-04 s: past the stability limit"},
    {"exponents", "--dt 1e-4", "--dt 1e-04 s: past the stability limit"},
    {"spreading", "--dt 2e-6 --fit-step 5e-6", "--fit-step"},  // stable: the grid is still checked
    {"spectrum", "--disorder RDM3", "--disorder"},
    {"spectrum", "--quasi s3", "--quasi"},
    {"spectrum", "--quasi s2 --modulation 1", "--modulation"},
    {"spectrum", "--quasi s2 --ratio 0", "--ratio"},
    {"spectrum", "--quasi s2 --ratio -0.5", "--ratio"},
    {"spectrum", "--quasi s1 --k0 0", "--k0"},
    {"spectrum", "--quasi cylinders --angle 200", "--angle"},
    {"spectrum", "--quasi cylinders --angle 150 --modulation 0.5", "--modulation"},
    // Axes so near parallel that the contact ellipse is a line (docs/physics.md, "C — cylinders").
    {"spectrum", "--quasi cylinders --modulation 0.99", "--modulation"},
    {"butterfly", "--quasi cylinders --angle 0.5 --modulation 0 --ratios 0.5", "--angle"},
    {"spectrum", "--quasi s2 --config x.txt", "--config"},
    {"localization", "--quasi s2 --modulation -1.5 --f 10", "--modulation"},
    {"localization", "--quasi s1 --k0 -1 --f 10", "--k0"},
    {"spreading", "--quasi s2 --ratio 0 --T 1e-4", "--ratio"},
    {"exponents", "--chains none --quasi s1 --F0 10 --modulation 1.5", "--modulation"},
    {"exponents", "--chains none --quasi s1", "--F0"},
    {"exponents", "--quasi s2 --polydisperse uniform:0.004:0.005", "--quasi"},
    {"ipr-map", "--quasi s2 --modulation 2", "--modulation"},
    {"butterfly", "--ratios 0,0.5", "--ratios"},
    {"butterfly", "--quasi s2 --modulation 1.2", "--modulation"},
    {"butterfly", "--smallest-box 0", "--smallest-box"},
    {"butterfly", "--from spin", "--from"},
    {"butterfly", "--T 1e-3", "--T"},  // a flag of --from dynamics in the eigen mode
    {"butterfly", "--from dynamics --box-sizes 5", "--box-sizes"},
    {"butterfly", "--from dynamics --N 20 --ratios 0,0.5", "--ratios"},
    {"butterfly", "--from dynamics --N 20 --amplitude 0", "--amplitude"},
    {"butterfly", "--from dynamics --N 20 --amplitude 1", "--amplitude"},  // would open contacts: not linear
    {"butterfly", "--from dynamics --N 20 --spectrum-samples 101",
     "--spectrum-samples"},  // Nyquist 5 kHz: aliased peaks
    {"butterfly", "--from dynamics --N 20 --spectrum-samples 3000",
     "--spectrum-samples"},  // 2999 intervals do not divide 10000 steps
    {"butterfly", "--from dynamics --N 20 --dt 1e-4", "--dt"},
    {"butterfly", "--from dynamics --N 20 --T -1", "--T"},
    {"butterfly", "--from dynamics --N 20 --integrator rk4", "--integrator"},
    {"spectrum", "--q 2", "--q"},
    {"spectrum", "--xi 1.01", "--xi"},
    {"spectrum", "--xi -0.5", "--xi"},
    {"spectrum", "--N 1", "--N"},
    {"spectrum", "--F0 -3", "--F0"},
    {"spectrum", "--F0 0", "F0"},
    {"spectrum", "--method arnoldi", "--method"},
    {"spectrum", "--config /nonexistent/chain.txt", "/nonexistent/chain.txt"},
    {"spectrum", "--radii /nonexistent/radii.txt", "/nonexistent/radii.txt"},
    {"spectrum", "--config " GRANULAR_DATA_DIR "/examples/single-impurity-11.radii", "single-impurity-11.radii:2"},
    {"spectrum", "--config a --radii b", "--config"},
    {"correlations", "--disorder Q", "--disorder"},
    {"correlations", "--disorder h", "--disorder"},
    {"correlations", "--q 1.2", "--q"},
    {"correlations", "--N 1", "--N"},
    {"correlations", "--realizations 0", "--realizations"},
    {"correlations", "--max-distance 100", "--max-distance"},
};

INSTANTIATE_TEST_SUITE_P(Tools, BadInputTest, ::testing::ValuesIn(cases));

TEST(ToolContract, HelpAndVersionExitZero) {
  for (const char* tool : {"ipr-map", "spectrum", "correlations"}) {
    EXPECT_EQ(run_tool(tool, "--help").exit_code, 0) << tool;
    EXPECT_EQ(run_tool(tool, "--version").exit_code, 0) << tool;
  }
}

TEST(ToolContract, UnwritableOutputFolderIsAnIoErrorWithNoOutput) {
  const ToolResult r = run_tool("spectrum", "--N 5 --output /nonexistent-folder/x.csv");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("/nonexistent-folder"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace granular::testing
