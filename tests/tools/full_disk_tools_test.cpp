// Real tools on a full disk: outputs and checkpoints on a 64 KiB tmpfs, mounted
// when the tests run as root (CI does; otherwise each test says loudly that it was skipped). A tool
// that runs out of space exits 1 with one line naming the file and "No space left on device",
// leaves no partial output, keeps its checkpoint readable, and once space is freed (the tmpfs
// remounted bigger) a --resume ends byte-identical to a run on a roomy disk.
#include <sys/mount.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tool_runner.hpp"

namespace {

namespace fs = std::filesystem;
using granular::testing::read_file;
using granular::testing::run_tool_in;
using granular::testing::scratch_folder;
using granular::testing::ToolResult;

class FullDiskTools : public ::testing::Test {
 protected:
  void SetUp() override {
    disk_ = fs::path(GRANULAR_BINARY_DIR) / ("full_disk_tools_" + std::to_string(::getpid()));
    fs::create_directories(disk_);
    if (::geteuid() != 0 || ::mount("tmpfs", disk_.c_str(), "tmpfs", 0, "size=64k") != 0)
      GTEST_SKIP() << "SKIPPED LOUDLY: mounting a 64 KiB tmpfs needs root (CAP_SYS_ADMIN); the tool-level full-disk "
                      "checks did not run";
    mounted_ = true;
  }
  void TearDown() override {
    if (mounted_) ::umount(disk_.c_str());
    std::error_code ec;
    fs::remove_all(disk_, ec);
  }
  /// Frees space: the same tmpfs, its files kept, remounted with room to spare.
  void grow() { ASSERT_EQ(::mount("tmpfs", disk_.c_str(), "tmpfs", MS_REMOUNT, "size=64m"), 0); }
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(disk_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  fs::path disk_;
  bool mounted_ = false;
};

/// One line on stderr naming the file (`file`, or `other`: whichever was being written; a name that
/// starts so, as out.checkpoint.0 for out.checkpoint) and the cause.
void expect_disk_full_message(const ToolResult& r, const std::string& file, const std::string& other = "") {
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line, not a library's error stack:\n" << r.err;
  EXPECT_TRUE(r.err.find("'" + file) != std::string::npos ||
              (!other.empty() && r.err.find("'" + other) != std::string::npos))
      << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
}

TEST_F(FullDiskTools, SpreadingEnergyMapThatDoesNotFitLeavesNothing) {
  // 500 times x 201 beads x 8 bytes = 800 kB into 64 kB
  const std::string args = "--N 201 --T 1e-3 --samples 20 --energy-map map.h5 --map-samples 500 --quiet --output out";
  const ToolResult r = run_tool_in(disk_.string(), "spreading", args);
  expect_disk_full_message(r, "map.h5");
  EXPECT_TRUE(files().empty()) << files().front();
  grow();
  const ToolResult again = run_tool_in(disk_.string(), "spreading", args);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  const std::string roomy = scratch_folder("full-disk-spreading");
  ASSERT_EQ(run_tool_in(roomy, "spreading", args).exit_code, 0);
  EXPECT_EQ(read_file((disk_ / "out.csv").string()), read_file(roomy + "/out.csv"));
  fs::remove_all(roomy);
}

TEST_F(FullDiskTools, IprMapThatDoesNotFitLeavesNothing) {
  // 5,700 rows (~340 kB) into 64 kB
  const std::string args = "--xi 0.1:1:0.05 --realizations 2 --threads 2 --quiet --output map.csv";
  const ToolResult r = run_tool_in(disk_.string(), "ipr-map", args);
  expect_disk_full_message(r, "map.csv", "map.json");  // the JSON is written first
  EXPECT_TRUE(files().empty()) << files().front();
  grow();
  ASSERT_EQ(run_tool_in(disk_.string(), "ipr-map", args).exit_code, 0);
  const std::string roomy = scratch_folder("full-disk-ipr-map");
  ASSERT_EQ(run_tool_in(roomy, "ipr-map", args).exit_code, 0);
  EXPECT_EQ(read_file((disk_ / "map.csv").string()), read_file(roomy + "/map.csv"));
  fs::remove_all(roomy);
}

TEST_F(FullDiskTools, ExponentsCheckpointFillsTheDiskThenResumesToTheSameBytes) {
  const std::string args =
      "--chains A --F0 10 --ic displacement --N 101 --T 1e-3 --fit 4e-4:1e-3 --t-star 4e-4 --realizations 24 "
      "--bootstrap 20 --profile-F0 none --threads 1 --quiet --output out";
  const ToolResult r = run_tool_in(disk_.string(), "exponents", args);
  expect_disk_full_message(r, "out.checkpoint");
  for (const auto& name : files()) EXPECT_TRUE(name.starts_with("out.checkpoint")) << "partial output " << name;
  ASSERT_FALSE(files().empty()) << "the checkpoint of the finished realizations is kept";
  grow();
  const ToolResult resumed = run_tool_in(disk_.string(), "exponents", args + " --resume");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const std::string roomy = scratch_folder("full-disk-exponents");
  ASSERT_EQ(run_tool_in(roomy, "exponents", args).exit_code, 0);
  for (const char* name : {"out.csv", "out-curves.csv"})
    EXPECT_EQ(read_file((disk_ / name).string()), read_file(roomy + "/" + name)) << name;
  fs::remove_all(roomy);
}

}  // namespace
