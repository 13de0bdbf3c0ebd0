// Outputs and checkpoints on a full disk: a 64 KiB tmpfs, mounted when the tests run as
// root (CI does); otherwise the test says loudly that it was skipped. Every failure must name the
// file and the cause, leave no partial output, and leave the checkpoint readable.
#include <sys/mount.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/error.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/hdf5_file.hpp"

namespace granular {
namespace {

class FullDisk : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::path(GRANULAR_BINARY_DIR) / ("full_disk_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    if (::geteuid() != 0 || ::mount("tmpfs", dir_.c_str(), "tmpfs", 0, "size=64k") != 0)
      GTEST_SKIP()
          << "SKIPPED LOUDLY: mounting a 64 KiB tmpfs needs root (CAP_SYS_ADMIN); the full-disk checks did not run";
    mounted_ = true;
  }
  void TearDown() override {
    if (mounted_) ::umount(dir_.c_str());
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    return names;
  }
  std::filesystem::path dir_;
  bool mounted_ = false;
};

void expect_names_file_and_cause(const IoError& e, const std::string& file) {
  const std::string what = e.what();
  EXPECT_NE(what.find(file), std::string::npos) << what;
  EXPECT_NE(what.find("No space left on device"), std::string::npos) << what;
}

TEST_F(FullDisk, AnAtomicFileThatDoesNotFitLeavesNothing) {
  try {
    AtomicFile out(path("big.csv"));
    const std::string line(1000, 'x');
    for (int i = 0; i < 200; ++i) out.stream() << line << '\n';  // 200 kB into 64 kB
    out.commit();
    ADD_FAILURE() << "commit succeeded on a full disk";
  } catch (const IoError& e) {
    expect_names_file_and_cause(e, "big.csv");
  }
  EXPECT_TRUE(files().empty()) << files().front();
}

TEST_F(FullDisk, AnHdf5FileThatDoesNotFitLeavesNothing) {
  const std::vector<double> data(20000, 1.0);  // 160 kB
  try {
    Hdf5File out(path("map.h5"));
    out.write("energy", data);
    out.commit();
    ADD_FAILURE() << "HDF5 commit succeeded on a full disk";
  } catch (const IoError& e) {
    expect_names_file_and_cause(e, "map.h5");
  }
  EXPECT_TRUE(files().empty());
}

TEST_F(FullDisk, ACheckpointThatFillsTheDiskStaysReadable) {
  const std::string log = path("run.checkpoint");
  const std::vector<double> values(300, 0.123456789012345);  // ~6 kB a line
  std::size_t appended = 0;
  try {
    CheckpointLog checkpoint(log, "{\"case\":1}");
    for (std::uint64_t r = 0; r < 100; ++r) {
      checkpoint.append(r, values);
      ++appended;
    }
    ADD_FAILURE() << "100 lines of 6 kB fit in 64 kB";
  } catch (const IoError& e) {
    expect_names_file_and_cause(e, "run.checkpoint");
  }
  ASSERT_GT(appended, 0u);
  // Every line that was reported appended reads back; the torn one is dropped.
  const CheckpointRecords records = CheckpointLog::load(log, "{\"case\":1}");
  EXPECT_EQ(records.size(), appended);
  for (const auto& [index, v] : records) EXPECT_EQ(v, values) << index;
  // Space freed (the run's other files deleted): a resumed log is rewritten whole.
  std::filesystem::remove(log);
  CheckpointLog resumed(log, "{\"case\":1}", records);
  EXPECT_EQ(CheckpointLog::load(log, "{\"case\":1}").size(), appended);
}

}  // namespace
}  // namespace granular
