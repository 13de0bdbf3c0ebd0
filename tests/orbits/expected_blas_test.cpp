// Which BLAS and LAPACK the test program runs on, checked when the run asks for one. The
// reference-BLAS runs of the long breather, Newton–Krylov and ARPACK tests (tests/CMakeLists.txt,
// label reference_blas) put Debian's reference libraries first on LD_LIBRARY_PATH and name their
// folders in GRANULAR_EXPECT_BLAS_DIR and GRANULAR_EXPECT_LAPACK_DIR; a global test environment
// then fails the program before any test when dgemv_ or dgeev_ come from elsewhere, or when any
// other BLAS (OpenBLAS) is mapped into the process, so that such a run cannot pass on OpenBLAS.
// Without those variables it does nothing.
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>

#include <gtest/gtest.h>

namespace granular {
namespace {

/// The file `symbol` was bound from in this process, symbolic links resolved; "" when none.
std::string expected_blas_file_of(const char* symbol) {
  void* address = dlsym(RTLD_DEFAULT, symbol);
  Dl_info info{};
  if (address == nullptr || dladdr(address, &info) == 0 || info.dli_fname == nullptr) return "";
  std::error_code error;
  const auto file = std::filesystem::canonical(info.dli_fname, error);
  return error ? std::string(info.dli_fname) : file.string();
}

std::string expected_blas_folder(const char* dir) {
  std::error_code error;
  const auto folder = std::filesystem::canonical(dir, error);
  return (error ? std::string(dir) : folder.string()) + "/";
}

/// "" when dgemv_ comes from a file in blas_dir and dgeev_ from one in lapack_dir (each null:
/// not checked) and no mapping of `maps` (/proc/self/maps) is an OpenBLAS outside those folders;
/// otherwise what differs.
std::string expected_blas_mismatch(const char* blas_dir, const char* lapack_dir, const std::string& maps) {
  std::string problem;
  const auto check = [&](const char* dir, const char* symbol) {
    if (dir == nullptr) return;
    const std::string folder = expected_blas_folder(dir), file = expected_blas_file_of(symbol);
    if (!file.starts_with(folder))
      problem += std::string(symbol) + " from '" + file + "', not from a file in '" + folder + "'; ";
  };
  check(blas_dir, "dgemv_");
  check(lapack_dir, "dgeev_");
  if (blas_dir == nullptr && lapack_dir == nullptr) return problem;
  std::istringstream lines(maps);
  for (std::string line; std::getline(lines, line);) {
    const auto slash = line.find('/');
    if (slash == std::string::npos) continue;
    const std::string path = line.substr(slash);
    if (path.find("openblas") == std::string::npos) continue;
    const bool expected = (blas_dir != nullptr && path.starts_with(expected_blas_folder(blas_dir))) ||
                          (lapack_dir != nullptr && path.starts_with(expected_blas_folder(lapack_dir)));
    if (!expected && problem.find(path) == std::string::npos) problem += "also mapped: '" + path + "'; ";
  }
  return problem;
}

std::string expected_blas_maps() {
  std::ifstream in("/proc/self/maps");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class ExpectedBlasEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    const char* blas = std::getenv("GRANULAR_EXPECT_BLAS_DIR");
    const char* lapack = std::getenv("GRANULAR_EXPECT_LAPACK_DIR");
    if (blas == nullptr && lapack == nullptr) return;
    std::printf("BLAS under test: dgemv_ from %s, dgeev_ from %s\n", expected_blas_file_of("dgemv_").c_str(),
                expected_blas_file_of("dgeev_").c_str());
    const std::string problem = expected_blas_mismatch(blas, lapack, expected_blas_maps());
    ASSERT_TRUE(problem.empty()) << "not the BLAS/LAPACK this run asks for: " << problem;
  }
};

[[maybe_unused]] ::testing::Environment* const expected_blas_environment =
    ::testing::AddGlobalTestEnvironment(new ExpectedBlasEnvironment);

std::string expected_blas_parent(const std::string& file) { return std::filesystem::path(file).parent_path().string(); }

// The check itself, on whichever BLAS this run has: the folders the routines came from pass, a
// folder they did not come from fails naming the routine, and an OpenBLAS mapped beside the
// expected libraries fails naming its file.
TEST(ExpectedBlas, AcceptsTheLoadedLibrariesAndNamesAnyOther) {
  const std::string blas = expected_blas_file_of("dgemv_"), lapack = expected_blas_file_of("dgeev_");
  ASSERT_FALSE(blas.empty());
  ASSERT_FALSE(lapack.empty());
  const std::string blas_dir = expected_blas_parent(blas), lapack_dir = expected_blas_parent(lapack);
  EXPECT_EQ(expected_blas_mismatch(blas_dir.c_str(), lapack_dir.c_str(), ""), "");
  EXPECT_EQ(expected_blas_mismatch(nullptr, nullptr, "7f00-7f01 r-xp 0 08:01 1 /opt/openblas/libopenblas.so.0\n"), "");
  const std::string elsewhere = ::testing::TempDir();
  EXPECT_NE(expected_blas_mismatch(elsewhere.c_str(), nullptr, "").find("dgemv_ from '" + blas + "'"),
            std::string::npos);
  EXPECT_NE(expected_blas_mismatch(nullptr, elsewhere.c_str(), "").find("dgeev_ from '" + lapack + "'"),
            std::string::npos);
  const std::string other = "7f00-7f01 r-xp 0 08:01 1 /opt/openblas/libopenblas.so.0\n";
  EXPECT_NE(expected_blas_mismatch(blas_dir.c_str(), lapack_dir.c_str(), other).find("also mapped: '/opt/openblas/"),
            std::string::npos);
}

}  // namespace
}  // namespace granular
