// Unit slips a new user makes — millimetres typed as metres, Hz as kHz, milliseconds as seconds —
// each draw one warning line naming the option, and the run goes on (or stops for its own
// reason). The same values typed correctly draw none.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "tool_runner.hpp"

namespace granular::testing {
namespace {

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

int lines(const std::string& text) { return count(text, "\n"); }

TEST(UnitSlip, RadiusInMetresIsWarnedOnceByEveryChainTool) {
  const std::string dir = scratch_folder("unit-slip-radius");
  for (const auto& [tool, args] : {std::pair<std::string, std::string>{"spectrum", "--N 20"},
                                   {"ipr-map", "--N 10 --xi 0.5 --q 0.5 --realizations 2"},
                                   {"localization", "--N 1000 --f 10"},
                                   {"spreading", "--N 51 --T 1e-4 --fit 2e-5:1e-4 --samples 20"}}) {
    const ToolResult slip = run_tool_in(dir, tool, args + " --R1 4.76 --quiet --output slip-" + tool);
    EXPECT_EQ(slip.exit_code, 0) << tool << ": " << slip.err;
    EXPECT_EQ(count(slip.err, "warning: --R1: radius 4.76 m"), 1) << tool << ": " << slip.err;
    const ToolResult right = run_tool_in(dir, tool, args + " --R1 4.76e-3 --quiet --output right-" + tool);
    EXPECT_EQ(right.exit_code, 0) << tool << ": " << right.err;
    EXPECT_EQ(count(right.err, "warning"), 0) << tool << ": " << right.err;
  }
}

TEST(UnitSlip, ATypeRadiusInMetresIsWarnedOnce) {
  const std::string dir = scratch_folder("unit-slip-types");
  const ToolResult r = run_tool_in(dir, "spreading",
                                   "--N 51 --T 1e-4 --fit 2e-5:1e-4 --samples 20 --types 4.76e-3:0.5,4.76:0.5 --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count(r.err, "warning: --types: radius 4.76 m"), 1) << r.err;
}

TEST(UnitSlip, HertzTypedAsKilohertzIsWarned) {
  const std::string dir = scratch_folder("unit-slip-frequency");
  const ToolResult near = run_tool_in(dir, "spectrum", "--N 100 --near 15000 --count 3 --quiet");
  EXPECT_EQ(near.exit_code, 0) << near.err;
  EXPECT_EQ(near.err.rfind("warning: --near 15000: above every frequency of this chain", 0), 0u) << near.err;
  EXPECT_EQ(lines(near.err), 1) << near.err;
  const ToolResult f = run_tool_in(dir, "localization", "--N 1000 --f 15000 --quiet --output loc");
  EXPECT_EQ(f.exit_code, 0) << f.err;
  EXPECT_EQ(f.err.rfind("warning: --f 15000: above every frequency of this chain", 0), 0u) << f.err;
  EXPECT_EQ(lines(f.err), 1) << f.err;
  const ToolResult khz = run_tool_in(dir, "spectrum", "--N 100 --near 15 --count 3 --quiet --output khz");
  EXPECT_EQ(khz.err, "");
}

// Every other frequency option of every tool, by the same rule (study/frequency_slips.hpp): one
// warning line naming the option before the run goes on or stops for its own reason.
TEST(UnitSlip, HertzTypedAsKilohertzIsWarnedForEveryFrequencyOption) {
  const std::string dir = scratch_folder("unit-slip-every-frequency");
  const std::string breathers = "--N 21 --max-points 1 --quiet ";
  for (const auto& [tool, args, named] :
       {std::tuple<std::string, std::string, std::string>{"breathers", breathers + "--near 33810", "--near 33810"},
        {"breathers", breathers + "--start-khz 20000", "--start-khz 20000"},
        {"breathers", breathers + "--mode 21 --target-khz 20000", "--target-khz 20000"},
        {"ipr-map", "--N 10 --xi 0.5 --q 0.5 --realizations 2 --near 15000 --count 2 --quiet", "--near 15000"},
        {"ipr-map", "--N 10 --xi 0.5 --q 0.5 --realizations 2 --window 15000:16000 --quiet", "--window 15000"},
        {"spreading", "--N 51 --T 1e-4 --fit 2e-5:1e-4 --samples 20 --ic mode --near 15000 --energy 1e-9 --quiet",
         "--near 15000"},
        {"exponents",
         "--chains none --quasi s2 --N 51 --T 1e-4 --fit 2e-5:1e-4 --t-star 2e-5 --realizations 1 "
         "--F0 10 --profile-F0 none --bootstrap 2 --ic mode --near 15000 --energy 1e-9",
         "--near 15000"}}) {
    const ToolResult slip = run_tool_in(dir, tool, args + " --output slip");
    EXPECT_EQ(slip.err.rfind("warning: " + named + ": above every frequency of this chain", 0), 0u)
        << tool << " " << args << ": " << slip.err;
    EXPECT_EQ(count(slip.err, "warning"), 1) << tool << " " << args << ": " << slip.err;
  }
  const ToolResult khz = run_tool_in(dir, "breathers", breathers + "--near 42 --output khz");
  EXPECT_EQ(khz.exit_code, 0) << khz.err;
  EXPECT_EQ(khz.err, "");
}

TEST(UnitSlip, SecondsTypedAsMillisecondsIsWarnedBeforeTheRun) {
  // T = 10 s on the paper's 2501 beads: the warning comes before the run, which then stops at
  // its missing output folder (an I/O error, exit 1), so the test does not integrate 10 s.
  const ToolResult slip = run_tool("spreading", "--T 10 --output /nonexistent-granular-folder/run");
  EXPECT_EQ(slip.exit_code, 1) << slip.err;
  EXPECT_EQ(slip.err.rfind("warning: --T 10: waves from the kick reach a wall after about", 0), 0u) << slip.err;
  const ToolResult paper = run_tool("spreading", "--T 1e-2 --output /nonexistent-granular-folder/run");
  EXPECT_EQ(paper.exit_code, 1) << paper.err;
  EXPECT_EQ(count(paper.err, "warning"), 0) << paper.err;
}

// Not a slip but the model's edge, warned the same way (issue 42, item 7): cylinders whose axes
// come near parallel, where the contact ellipse grows towards the cylinders' size (docs/physics.md,
// "C — cylinders"): one warning line naming --modulation or --angle above 0.1 R, exit 2 from 0.5 R.
TEST(UnitSlip, CylindersNearParallelAreWarnedThenRefused) {
  const std::string dir = scratch_folder("cylinder-ellipse");
  const ToolResult warned = run_tool_in(dir, "spectrum", "--quasi cylinders --modulation 0.9 --N 20 --quiet");
  EXPECT_EQ(warned.exit_code, 0) << warned.err;
  EXPECT_EQ(warned.err.rfind("warning: --modulation 0.9: at 4.5 degrees the cylinders' contact ellipse", 0), 0u)
      << warned.err;
  EXPECT_EQ(lines(warned.err), 1) << warned.err;
  const ToolResult angle = run_tool_in(dir, "spectrum", "--quasi cylinders --angle 5 --N 20 --quiet --output a");
  EXPECT_EQ(angle.exit_code, 0) << angle.err;
  EXPECT_EQ(angle.err.rfind("warning: --angle 5: at 5 degrees", 0), 0u) << angle.err;
  const ToolResult fine = run_tool_in(dir, "spectrum", "--quasi cylinders --modulation 0.5 --N 20 --quiet --output f");
  EXPECT_EQ(fine.err, "");
  const ToolResult refused =
      run_tool_in(dir, "spectrum", "--quasi cylinders --modulation 0.99 --N 20 --quiet --output r");
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("--modulation 0.99: at 0.45 degrees"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("beyond the point-contact (Hertz) law"), std::string::npos) << refused.err;
  EXPECT_EQ(lines(refused.err), 1) << refused.err;
}

}  // namespace
}  // namespace granular::testing
