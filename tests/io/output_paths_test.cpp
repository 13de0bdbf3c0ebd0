// One --output rule for every tool, and outputs checked before a run, not after it.
#include "granular/io/output_paths.hpp"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "scratch.hpp"

namespace granular {
namespace {

TEST(OutputPaths, ATrailingCsvIsDroppedAndNothingElse) {
  EXPECT_EQ(output_prefix("run"), "run");
  EXPECT_EQ(output_prefix("run.csv"), "run");
  EXPECT_EQ(output_prefix("dir/run.csv"), "dir/run");
  EXPECT_EQ(output_prefix(".csv"), ".csv");  // nothing would be left
  EXPECT_EQ(output_prefix("run.json"), "run.json");
  EXPECT_EQ(output_prefix("run.csv.csv"), "run.csv");
}

TEST(OutputPaths, TwoOutputsOnOneFileAreRefusedNamingThem) {
  const std::string a = testing::scratch_path("output_paths_test", "a.csv");
  const std::string b = testing::scratch_path("output_paths_test", "b.csv");
  const auto dir = std::filesystem::path(a).parent_path();
  EXPECT_NO_THROW(check_outputs({a, "", b}, "--x/--y"));
  try {
    check_outputs({a, b, (dir / "sub" / ".." / "a.csv").string()}, "--x/--y");
    FAIL() << "two outputs on one file were accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--x/--y: two outputs would both be ", 0), 0u) << e.what();
  }
  EXPECT_THROW(check_outputs({(dir / "no-such-folder" / "a.csv").string()}, "--x"), IoError);
}

}  // namespace
}  // namespace granular
