// An option that takes effect only with another choice (the rows of the library's tables that
// name what they need, Parameter::needs) is refused without it — exit 2, one line naming both
// flags, no output — by every tool that takes it, and runs with it. Every such row is covered:
// a new one fails here until it has a value below.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "granular/case/chain_choices.hpp"
#include "granular/case/spreading_outputs.hpp"
#include "granular/case/transport_parameters.hpp"
#include "granular/parameter_names.hpp"
#include "tool_runner.hpp"

namespace granular::testing {
namespace {

/// A dependent option's test: a value other than its default, what leaves its need unmet (added
/// to the option), and what meets it.
struct Case {
  std::string value, unmet, met;
};

/// The tools that take a table's options, and the flags they give a needed choice where the usual
/// rule is not theirs (spreading's --spectrum FILE asks for the spectral density).
struct Takers {
  std::vector<std::string> tools;
  std::map<std::string, std::string> flags{};
};

// Runs that finish in well under a second, one per table: a chain's and a kicked run's.
const std::string chain_run = "spectrum", chain_args = "--N 20 --quiet";
const std::string kick_run = "spreading", kick_args = "--N 51 --T 1e-4 --fit 2e-5:1e-4 --samples 20 --quiet";

template <class Choices>
void check_table(const ParameterTable<Choices>& table, const std::map<std::string, Case>& cases, const Takers& takers,
                 const std::string& met_tool, const std::string& met_args) {
  for (const Parameter<Choices>& p : table) {
    if (!p.needs) continue;
    const auto it = cases.find(p.name);
    ASSERT_NE(it, cases.end()) << p.name << " needs `" << p.needs->choice << "` but has no case here";
    const Case& c = it->second;
    const auto named = takers.flags.find(p.needs->choice);
    const std::string flag = flag_for(p.name),
                      needed = named != takers.flags.end() ? named->second : flag_for(p.needs->choice);
    int taken = 0;
    for (const std::string& tool : takers.tools) {
      if (tool_help(tool).find(flag + " ") == std::string::npos) continue;  // a tool may take part of a table
      ++taken;
      const std::string dir = scratch_folder("dependent-" + p.name + "-" + tool);
      const ToolResult r = run_tool_in(dir, tool, flag + " " + c.value + " " + c.unmet + " --output out");
      EXPECT_EQ(r.exit_code, 2) << tool << " " << flag << ": " << r.err;
      EXPECT_NE(r.err.find("error: " + flag + ": takes effect only with " + needed), std::string::npos)
          << tool << " " << flag << ": " << r.err;
      EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << tool << ": one line: " << r.err;
      EXPECT_TRUE(std::filesystem::is_empty(dir)) << tool << " " << flag << " wrote an output";
    }
    EXPECT_GT(taken, 0) << flag;
    const std::string dir = scratch_folder("dependent-met-" + p.name);
    const ToolResult met = run_tool_in(dir, met_tool, met_args + " " + flag + " " + c.value + " " + c.met);
    EXPECT_EQ(met.exit_code, 0) << met_tool << " " << flag << " " << c.met << ": " << met.err;
  }
}

TEST(DependentOptions, ChainOptionsAreRefusedWithoutTheChainTheyNeed) {
  check_table(chain_parameters(),
              {{"modulation", {"0.5", "", "--quasi s2"}},
               {"ratio", {"2/7", "", "--quasi s2"}},
               {"phase", {"0.4", "", "--quasi S2"}},
               {"angle", {"30", "--quasi s1", "--quasi cylinders"}},
               {"k0", {"8", "", "--quasi s1"}},
               {"k0_n_per_m", {"1e6", "--quasi s2", "--quasi s1"}}},
              {{"spectrum", "localization", "spreading", "ipr-map", "breathers", "exponents"}}, chain_run, chain_args);
  // butterfly always has a quasiperiodic chain (--quasi s1 by default): its kinds' options are checked.
  const std::string dir = scratch_folder("dependent-butterfly");
  for (const auto& [args, message] :
       {std::pair<std::string, std::string>{"--angle 30",
                                            "--angle: takes effect only with --quasi cylinders, not "
                                            "--quasi s1"},
        {"--quasi s2 --k0 8", "--k0: takes effect only with --quasi s1, not --quasi s2"}}) {
    const ToolResult r = run_tool_in(dir, "butterfly", args + " --output out");
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(r.err, "butterfly: error: " + message + "\n");
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// A chain option that another chain choice overrides (Parameter::overridden_by: `q` with `quasi`,
// `xi` with `radii`, ...) is refused with it, naming both, for every pair of the table.
TEST(DependentOptions, ChainOptionsAreRefusedWithTheChoiceThatOverridesThem) {
  const std::string dir = scratch_folder("dependent-overridden");
  {
    std::ofstream radii(dir + "/chain.radii");
    radii << "4e-3\n3e-3\n4e-3\n";
  }
  const std::map<std::string, std::string> values{{"disorder", "RDM1"}, {"xi", "0.6"}, {"q", "0.3"},        {"N", "50"},
                                                  {"R1", "5e-3"},       {"seed", "7"}, {"realization", "2"}};
  // Each overriding choice: its arguments, and how the message tells it.
  const std::map<std::string, std::pair<std::string, std::string>> choices{
      {"config", {"--config " GRANULAR_DATA_DIR "/examples/diatomic-10.types", "--config"}},
      {"radii", {"--radii " + dir + "/chain.radii", "--radii"}},
      {"types", {"--types 4e-3:0.5,3e-3:0.5", "--types"}},
      {"type_masses", {"--type-masses 3.5e-3:0.5,1e-3:0.5", "--type-masses"}},
      {"polydisperse", {"--polydisperse uniform:3e-3:5e-3", "--polydisperse"}},
      {"quasi", {"--quasi s2", "--quasi"}},
      {"phase", {"--quasi s2 --phase 0.4", "--phase"}},
      {"disorder h homogeneous", {"--disorder h", "--disorder h"}}};
  int pairs = 0;
  for (const Parameter<ChainChoices>& p : chain_parameters())
    for (const std::string& choice : p.overridden_by) {
      ASSERT_TRUE(values.contains(p.name)) << p.name << " has no value here";
      ASSERT_TRUE(choices.contains(choice)) << choice << " has no arguments here";
      const auto& [choice_args, told] = choices.at(choice);
      const std::string args = flag_for(p.name) + " " + values.at(p.name) + " " + choice_args;
      const ToolResult r = run_tool_in(dir, chain_run, "--quiet " + args + " --output out");
      EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
      EXPECT_EQ(r.err,
                "spectrum: error: " + flag_for(p.name) + ": takes no effect with " + told + "; leave one of them out\n")
          << args;
      EXPECT_FALSE(std::filesystem::exists(dir + "/out.csv")) << args;
      ++pairs;
    }
  EXPECT_GE(pairs, 20);
  // Each value alone runs (the refusal is the pair's, not the value's).
  for (const auto& [name, value] : values)
    EXPECT_EQ(run_tool_in(dir, chain_run, "--quiet " + flag_for(name) + " " + value + " --output alone").exit_code, 0)
        << name;
}

TEST(DependentOptions, RunOptionsAreRefusedWithoutTheChoiceTheyNeed) {
  check_table(transport_parameters(),
              {{"window_threshold", {"1e-20", "--active-window off", ""}},
               {"reference_max_step", {"2e-8", "", "--integrator reference"}},
               {"energy_guard", {"warn", "--max-energy-error 0", ""}},
               {"renormalize", {"5", "", "--mle"}},
               {"norm_time_unit", {"2e-6", "", "--mle"}},
               {"deviation_samples", {"3", "--deviation dev.csv", "--mle --deviation dev.csv"}},
               {"lyapunov_vectors", {"2", "", "--mle"}},
               {"covariant_vectors", {"2", "", "--mle"}},
               {"covariant_transient", {"2e-5", "", "--mle --covariant-vectors 2"}}},
              {{"spreading", "exponents"}}, kick_run, kick_args);
  check_table(spreading_output_parameters(),
              {{"force_samples", {"50", "", "--forces-at 20"}},
               {"map_samples", {"50", "", "--energy-map map.h5"}},
               {"map_stride", {"2", "", "--energy-map map.h5"}},
               {"spectrum_samples", {"50", "", "--spectrum g.csv"}},
               {"spectrum_of", {"velocity", "", "--spectrum g.csv"}}},
              {{"spreading"}, {{"spectral_density", "--spectrum"}}}, kick_run, kick_args);
}

// spreading's --deviation-samples are the times of its --deviation FILE: refused without it.
TEST(DependentOptions, DeviationSamplesAreRefusedWithoutTheirFile) {
  const std::string dir = scratch_folder("dependent-deviation");
  const ToolResult r = run_tool_in(dir, "spreading", "--mle --deviation-samples 3 --output out");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err, "spreading: error: --deviation-samples: takes effect only with --deviation FILE (and --mle)\n");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// Settings of a solver or a seed that would not act are refused naming what they need, and taken
// where they act: spectrum's --lanes (selected modes), --tolerance (ARPACK, SLEPc); breathers'
// --near beside --mode (two seeds) and --start-offset beside --start-khz (the start is given).
TEST(DependentOptions, SolverAndSeedSettingsThatWouldNotActAreRefused) {
  const std::string dir = scratch_folder("dependent-solver-seed");
  for (const auto& [tool, args, message] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"spectrum", "--N 20 --lanes 4",
            "--lanes: takes effect only with selected modes (--near or --window), not with every mode"},
           {"spectrum", "--N 20 --near 15 --count 3 --tolerance 1e-8",
            "--tolerance: takes effect only with --method arpack or slepc, not --method lapack"},
           {"spectrum", "--N 20 --near 15 --count 3 --method bisect --tolerance 1e-8",
            "--tolerance: takes effect only with --method arpack or slepc, not --method bisect"},
           {"breathers", "--N 21 --mode 3 --near 30",
            "--near: give either a seed mode number (--mode) or a frequency to seed from (--near), not both"},
           {"breathers", "--N 21 --mode 3 --start-khz 30 --start-offset 1e-2",
            "--start-offset: takes effect only without --start-khz (it places the first frequency off the "
            "seed's), which is given"}}) {
    const ToolResult r = run_tool_in(dir, tool, args + " --output out");
    EXPECT_EQ(r.exit_code, 2) << tool << " " << args << ": " << r.err;
    EXPECT_EQ(r.err, tool + ": error: " + message + "\n");
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  for (const std::string args : {"--N 20 --near 15 --count 3 --method bisect --lanes 4",
                                 "--N 20 --near 15 --count 3 --method arpack --tolerance 1e-8"}) {
    const ToolResult r = run_tool_in(dir, "spectrum", args + " --quiet --output met");
    EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
  }
}

// The three commands, as typed.
TEST(DependentOptions, TheReportedCommandsAreRefused) {
  const std::string dir = scratch_folder("dependent-reported");
  for (const auto& [args, flag] : {std::pair<std::string, std::string>{"--modulation 0.5", "--modulation"},
                                   {"--k0 8 --phase 0.4", "--phase"},
                                   {"--angle 30 --quasi s1", "--angle"}}) {
    const ToolResult r = run_tool_in(dir, "spectrum", args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("spectrum: error: " + flag + ": takes effect only with --quasi", 0), 0u) << r.err;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace granular::testing
