// Renamed options (issue 41: one word per quantity): the former spelling still works for one minor
// version, gives exactly the run the new one gives, and says once on stderr which word to use; it is
// no longer in --help. The nearest-frequency option of a mode kick was --mode-khz, now --near (as
// `spectrum` and `ipr-map` have it).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "tool_runner.hpp"

namespace {

using granular::testing::read_file;
using granular::testing::run_tool_in;
using granular::testing::scratch_folder;

/// What `tool args` prints on stdout.
std::string standard_output(const std::string& tool, const std::string& args) {
  std::string out;
  std::string command = granular::testing::tool_path(tool);
  command += " " + args;
  command += " 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  for (char buffer[4096]; pipe && std::fgets(buffer, sizeof buffer, pipe);) out += buffer;
  if (pipe) ::pclose(pipe);
  return out;
}

const std::string kick = "--N 51 --T 1e-4 --fit 2e-5:1e-4 --samples 20 --ic mode --energy 1e-9 --quiet ";

TEST(RenamedOptions, TheFormerSpellingRunsTheSameCaseWithANote) {
  const std::string dir = scratch_folder("renamed-mode-khz");
  const auto now = run_tool_in(dir, "spreading", kick + "--near 20 --output now");
  ASSERT_EQ(now.exit_code, 0) << now.err;
  EXPECT_EQ(now.err, "");
  const auto before = run_tool_in(dir, "spreading", kick + "--mode-khz 20 --output before");
  ASSERT_EQ(before.exit_code, 0) << before.err;
  EXPECT_EQ(before.err,
            "warning: --mode-khz is deprecated: use --near (the old spelling goes in the next minor version)\n");
  EXPECT_EQ(read_file(dir + "/now.csv"), read_file(dir + "/before.csv"));
  const auto parameters = [&](const std::string& name) {
    return nlohmann::json::parse(read_file(dir + "/" + name + ".json"))["parameters"];
  };
  EXPECT_EQ(parameters("now"), parameters("before"));
  EXPECT_EQ(parameters("now")["near_khz"], 20.0);
}

// breathers' seed frequency was --near-khz: now --near as well.
TEST(RenamedOptions, TheBreathersSeedFrequencyIsNearToo) {
  const std::string dir = scratch_folder("renamed-near-khz");
  const std::string branch = "--N 21 --max-points 1 --quiet ";
  const auto now = run_tool_in(dir, "breathers", branch + "--near 42 --output now");
  ASSERT_EQ(now.exit_code, 0) << now.err;
  EXPECT_EQ(now.err, "");
  const auto before = run_tool_in(dir, "breathers", branch + "--near-khz 42 --output before");
  ASSERT_EQ(before.exit_code, 0) << before.err;
  EXPECT_EQ(before.err,
            "warning: --near-khz is deprecated: use --near (the old spelling goes in the next minor version)\n");
  EXPECT_EQ(read_file(dir + "/now.csv"), read_file(dir + "/before.csv"));
}

TEST(RenamedOptions, OnlyTheNewSpellingIsInTheHelp) {
  for (const char* tool : {"spreading", "exponents", "breathers"}) {
    const std::string help = standard_output(tool, "--help");
    EXPECT_NE(help.find("--near FLOAT"), std::string::npos) << tool;
    EXPECT_EQ(help.find("--mode-khz"), std::string::npos) << tool;
    EXPECT_EQ(help.find("--near-khz"), std::string::npos) << tool;
  }
}

}  // namespace
