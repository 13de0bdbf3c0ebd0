// One --output convention for every tool: the value is a prefix and a trailing .csv is dropped,
// so `--output a` and `--output a.csv` write the same files a.csv, a.json (and a-*.csv ...).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tools/tool_runner.hpp"

using namespace granular::testing;
namespace fs = std::filesystem;

namespace {

struct ToolCase {
  const char* tool;
  const char* args;
};

const ToolCase tool_cases[] = {
    {"spectrum", "--N 20 --disorder A --seed 3"},
    {"ipr-map", "--N 10 --xi 0.5 --q 0.5 --realizations 2 --threads 1"},
    {"correlations", "--N 20 --realizations 3 --max-distance 3 --threads 1"},
    {"localization", "--N 100 --f 1,2 --segments 2 --threads 1"},
    {"restitution", "--impact-speed 0.01 --kk-gamma 1e-6"},
    {"crystal", "--lattice hexagonal --Lx 4 --Ly 4 --vectors"},
    {"crystal-ipr-map", "--Lx 4 --Ly 4 --widths 0,0.5 --realizations 2 --threads 1"},
    {"spreading", "--N 51 --T 1e-4 --samples 5"},
    {"klein-gordon", "--N 32 --T 10 --samples 4 --realizations 2 --threads 1"},
    {"exponents",
     "--chains A --F0 10 --ic displacement --N 51 --T 2e-4 --fit 1e-4:2e-4 --t-star 1e-4 --realizations 2 "
     "--bootstrap 5 --profile-F0 none --threads 1"},
};

std::vector<std::string> files_in(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class OutputConvention : public ::testing::TestWithParam<ToolCase> {};

TEST_P(OutputConvention, PrefixAndPrefixDotCsvWriteTheSameFiles) {
  const ToolCase& c = GetParam();
  const std::string name = std::string("output-") + c.tool;
  const std::string bare = scratch_folder(name + "-bare"), dotted = scratch_folder(name + "-csv");
  const std::string args = std::string(c.args) + " --quiet --output ";
  ASSERT_EQ(run_tool_in(bare, c.tool, args + "a").exit_code, 0) << c.tool;
  ASSERT_EQ(run_tool_in(dotted, c.tool, args + "a.csv").exit_code, 0) << c.tool;
  const auto files = files_in(bare);
  EXPECT_EQ(files, files_in(dotted)) << c.tool;
  EXPECT_TRUE(std::count(files.begin(), files.end(), "a.csv") == 1) << c.tool;
  EXPECT_TRUE(std::count(files.begin(), files.end(), "a.json") == 1) << c.tool;
  EXPECT_TRUE(std::count(files.begin(), files.end(), "a.csv.csv") == 0) << c.tool;
  for (const auto& f : files) {
    if (!f.ends_with(".csv")) continue;
    EXPECT_EQ(read_file(bare + "/" + f), read_file(dotted + "/" + f)) << c.tool << " " << f;
  }
  const auto json = nlohmann::json::parse(read_file(bare + "/a.json"));
  EXPECT_EQ(json.at("output"), "a.csv") << c.tool;
  fs::remove_all(bare);
  fs::remove_all(dotted);
}

INSTANTIATE_TEST_SUITE_P(EveryTool, OutputConvention, ::testing::ValuesIn(tool_cases),
                         [](const ::testing::TestParamInfo<ToolCase>& info) {
                           std::string n = info.param.tool;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

}  // namespace
