// The temporary file behind AtomicFile and Hdf5File (io/detail/temporary_file.hpp): created new
// beside the target, never through a symlink or into a file that is there; a leftover of the same
// name (a killed run with the same pid) does not stop the next run; nothing is left without commit.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "granular/io/atomic_file.hpp"
#include "granular/io/hdf5_file.hpp"

namespace granular {
namespace {

namespace fs = std::filesystem;

class TemporaryFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(GRANULAR_BINARY_DIR) / ("temporary_file_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  /// The temporary name AtomicFile and Hdf5File use for `target`.
  static std::string temporary(const std::string& target) { return target + ".tmp." + std::to_string(::getpid()); }
  static std::string read(const std::string& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    return names;
  }
  fs::path dir_;
};

TEST_F(TemporaryFile, ALeftoverOfTheSameNameIsReplaced) {
  std::ofstream(temporary(path("out.csv"))) << "stale content of a killed run\n";
  write_file_atomically(path("out.csv"), "a,b\n1,2\n");
  EXPECT_EQ(read(path("out.csv")), "a,b\n1,2\n");
  EXPECT_EQ(files(), std::vector<std::string>{"out.csv"});
}

TEST_F(TemporaryFile, ASymlinkAtTheTemporaryNameIsNotFollowed) {
  std::ofstream(path("victim")) << "keep me\n";
  fs::create_symlink(path("victim"), temporary(path("out.csv")));
  write_file_atomically(path("out.csv"), "written\n");
  EXPECT_EQ(read(path("victim")), "keep me\n");
  EXPECT_EQ(read(path("out.csv")), "written\n");
  EXPECT_FALSE(fs::is_symlink(path("out.csv")));

  fs::create_symlink(path("victim"), temporary(path("out.h5")));
  const std::vector<double> x{1, 2, 3};
  write_hdf5_atomically(path("out.h5"), {{"x", {3}, x.data()}});
  EXPECT_EQ(read(path("victim")), "keep me\n");
  EXPECT_TRUE(fs::is_regular_file(path("out.h5")));
  EXPECT_FALSE(fs::exists(temporary(path("out.h5"))));
}

TEST_F(TemporaryFile, WithoutCommitNothingIsLeft) {
  {
    AtomicFile csv(path("a.csv"));
    csv.stream() << "partial";
    Hdf5File h5(path("b.h5"));
    h5.write("x", std::vector<double>{1.0});
  }
  EXPECT_TRUE(files().empty());
}

}  // namespace
}  // namespace granular
