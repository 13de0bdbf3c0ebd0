// Every name an output writer chooses predictably in a shared folder (the lock, the temporary
// beside an output or an HDF5 file, the writability probe) with a symlink planted at it, pointing
// at a victim file: the writer refuses or goes around it, and the victim is byte-identical after.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/hdf5_file.hpp"
#include "granular/io/output_lock.hpp"

namespace granular {
namespace {

namespace fs = std::filesystem;

class PlantedSymlink : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(GRANULAR_BINARY_DIR) / ("planted_symlink_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(victim(), std::ios::binary) << victim_text;
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string victim() const { return path("victim"); }
  void plant(const std::string& at) const { fs::create_symlink(victim(), at); }
  static std::string read(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  static std::string pid() { return std::to_string(::getpid()); }
  static constexpr const char* victim_text = "a file of the user's that no run may touch\n";
  fs::path dir_;
};

TEST_F(PlantedSymlink, AtTheLockTheRunIsRefused) {
  plant(path("run.lock"));
  try {
    OutputLock lock(path("run"), "spreading --output run");
    ADD_FAILURE() << "a lock was taken through a symlink";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "output");
    EXPECT_NE(std::string(e.what()).find("symbolic link"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(victim()), victim_text);
  EXPECT_TRUE(fs::is_symlink(path("run.lock")));  // left for the user to look at
}

TEST_F(PlantedSymlink, AHardLinkAtTheLockIsRefusedToo) {
  fs::create_hard_link(victim(), path("run.lock"));
  EXPECT_THROW(OutputLock(path("run")), InvalidInput);
  EXPECT_EQ(read(victim()), victim_text);
}

TEST_F(PlantedSymlink, AtTheTemporariesTheWriterGoesAround) {
  plant(path("out.csv.tmp." + pid()));
  write_file_atomically(path("out.csv"), "a,b\n");
  EXPECT_EQ(read(path("out.csv")), "a,b\n");
  plant(path("out.h5.tmp." + pid()));
  const std::vector<double> x{1, 2};
  write_hdf5_atomically(path("out.h5"), {{"x", {2}, x.data()}});
  EXPECT_TRUE(fs::is_regular_file(path("out.h5")));
  EXPECT_EQ(read(victim()), victim_text);
}

TEST_F(PlantedSymlink, AtTheWritabilityProbeNothingIsClobbered) {
  // The name the probe had when it was made from the pid.
  plant(path(".granular-probe." + pid()));
  check_writable(path("out.csv"));
  write_file_atomically(path("out.csv"), "a,b\n");
  EXPECT_EQ(read(victim()), victim_text);
  EXPECT_TRUE(fs::is_symlink(path(".granular-probe." + pid())));  // someone else's file: not removed either
}

TEST(OutputLockHolder, IsQuotedBoundedAndEscaped) {
  const auto dir = fs::path(GRANULAR_BINARY_DIR) / ("lock_holder_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string prefix = (dir / "run").string();
  std::string text = "process 1 (\x1b]0;owned\x07 spreading)";
  text += std::string(600, 'x');
  std::ofstream(prefix + ".lock", std::ios::binary) << text;
  const int fd = ::open((prefix + ".lock").c_str(), O_RDONLY);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);  // another open file description: the lock conflicts
  try {
    OutputLock second(prefix);
    ADD_FAILURE() << "the lock was granted twice";
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("process 1 (\\x1B]0;owned\\x07 spreading)"), std::string::npos) << what;
    for (char c : what) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "raw byte " << int(c) << " in: " << what;
    EXPECT_LT(what.size(), 400u) << what;
  }
  ::close(fd);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace granular
