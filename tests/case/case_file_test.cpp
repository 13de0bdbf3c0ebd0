// A case in a file of its own: the replay file of a failed realization holds the case run alone
// (every field but the ensemble's size), its name tells the cases of one study apart, and it reads
// back as that case, as does a run's JSON with the case under "parameters"; a file that is not a
// case is refused naming `case`.
#include "granular/case/case_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "scratch.hpp"

namespace granular {
namespace {

TransportCase case_file_example() {
  TransportCase c;
  c.chain = {.source = TwoTypeDraw{.disorder = Disorder::rdm1, .q = 0.3, .xi = 0.6}, .N = 101, .F0 = 0.5, .seed = 9};
  c.realizations = 40;
  c.profile_realizations = 40;
  c.dynamics.integration.duration = 2e-3;
  c.fit_begin = 1e-3;
  c.fit_end = 2e-3;
  c.dynamics.integration.damping.time = 1e-3;
  return c;
}

std::string case_file_parameter(const std::string& path) {
  try {
    read_case_file(path);
  } catch (const InvalidInput& e) {
    return e.parameter();
  }
  return "(accepted)";
}

TEST(CaseFile, AReplayFileReadsBackAsTheCaseRunAlone) {
  const std::string prefix = testing::scratch_path("case_file", "run");
  const TransportCase c = case_file_example();
  const std::string file = write_replay_case(c, 17, prefix);
  EXPECT_TRUE(file.starts_with(prefix + ".replay-17-")) << file;
  EXPECT_TRUE(file.ends_with(".json")) << file;
  const TransportCase back = read_case_file(file);
  TransportCase alone = c;
  alone.realizations = 1, alone.profile_realizations = 0;
  EXPECT_EQ(describe(back), describe(alone));
  EXPECT_EQ(back.realizations, 1u);
  // the same case gives the same file; another case of the study another one
  EXPECT_EQ(write_replay_case(c, 17, prefix), file);
  TransportCase other = c;
  other.chain.F0 = 0.1;
  EXPECT_NE(write_replay_case(other, 17, prefix), file);
}

TEST(CaseFile, ARunsJsonReadsAsItsParameters) {
  const std::string path = testing::scratch_path("case_file", "run.json");
  const TransportCase c = case_file_example();
  std::ofstream(path) << nlohmann::json{{"parameters", describe(c)}, {"output", "run.csv"}}.dump();
  EXPECT_EQ(describe(read_case_file(path)), describe(c));
}

TEST(CaseFile, WhatIsNoCaseIsRefusedNamingCase) {
  EXPECT_EQ(case_file_parameter(testing::scratch_path("case_file", "absent.json")), "case");
  const std::string list = testing::scratch_path("case_file", "list.json");
  std::ofstream(list) << "[1, 2]";
  EXPECT_EQ(case_file_parameter(list), "case");
  const std::string wrong = testing::scratch_path("case_file", "wrong.json");
  std::ofstream(wrong) << R"({"parameters": {"N": "many"}})";
  EXPECT_EQ(case_file_parameter(wrong), "case");
}

}  // namespace
}  // namespace granular
