// ipr-map end to end: determinism across thread counts and seeds.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tool_runner.hpp"

namespace granular::testing {
namespace {

const std::string small_job = "--N 24 --xi 0.3:0.5:0.1 --q 0.2,0.8 --realizations 12 --quiet";

TEST(IprMapTool, SameSeedIsByteIdenticalForOneAndTwoThreads) {
  const std::string dir = scratch_folder("ipr-threads");
  ASSERT_EQ(run_tool("ipr-map", small_job + " --seed 5 --threads 1 --output " + dir + "/t1.csv").exit_code, 0);
  ASSERT_EQ(run_tool("ipr-map", small_job + " --seed 5 --threads 2 --output " + dir + "/t2.csv").exit_code, 0);
  ASSERT_EQ(run_tool("ipr-map", small_job + " --seed 6 --threads 2 --output " + dir + "/s6.csv").exit_code, 0);
  const std::string one = read_file(dir + "/t1.csv"), two = read_file(dir + "/t2.csv"),
                    other = read_file(dir + "/s6.csv");
  EXPECT_EQ(one.substr(0, one.find('\n')), "disorder,q,xi,mode,freq_khz,ipr");
  EXPECT_EQ(std::count(one.begin(), one.end(), '\n'), 1 + 2 * 3 * 24);
  EXPECT_EQ(one, two);
  EXPECT_NE(one, other);
  EXPECT_NE(read_file(dir + "/t1.json").find("\"seed\": 5"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(IprMapTool, OneHomogeneousRealizationEqualsTheSpectrumTool) {
  // h ignores q and the seed: the map's single realization is the chain `spectrum` solves.
  // Same solver as `spectrum` (LAPACK) so the digits can match; ipr-map's default `fast` solver
  // agrees to ~1e-12 (tests/linear/twisted_ipr_solver_test.cpp), not to the last digit.
  const std::string dir = scratch_folder("ipr-h");
  ASSERT_EQ(run_tool("ipr-map",
                     "--disorder h --N 12 --xi 1 --q 0.5 --realizations 1 --solver lapack --quiet --output " + dir +
                         "/h.csv")
                .exit_code,
            0);
  ASSERT_EQ(run_tool("spectrum", "--disorder h --N 12 --output " + dir + "/s.csv").exit_code, 0);
  std::istringstream map(read_file(dir + "/h.csv")), spec(read_file(dir + "/s.csv"));
  std::string a, b;
  std::getline(map, a);
  std::getline(spec, b);
  int rows = 0;
  while (std::getline(map, a) && std::getline(spec, b)) {
    // "h,0.5,1,k,f,ipr" versus "k,f,ipr": the mode columns must agree to the last digit.
    EXPECT_EQ(a.substr(std::string("h,0.5,1,").size()), b);
    ++rows;
  }
  EXPECT_EQ(rows, 12);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace granular::testing

namespace granular::testing {
namespace {

// ipr-map --near/--count: the modes of each realization, identical for 1 and 2 threads, and those
// of realization r equal `spectrum --near` on realization r of the same seed.
TEST(IprMapTool, PartialSelectionMatchesSpectrumPerRealization) {
  const std::string dir = scratch_folder("ipr-partial");
  const std::string job =
      "--disorder RDM1 --N 3000 --xi 0.5 --q 0.5 --realizations 3 --near 15 --count 4 --method bisect --quiet";
  ASSERT_EQ(run_tool("ipr-map", job + " --threads 1 --output " + dir + "/t1.csv").exit_code, 0);
  ASSERT_EQ(run_tool("ipr-map", job + " --threads 2 --output " + dir + "/t2.csv").exit_code, 0);
  const std::string map = read_file(dir + "/t1.csv");
  EXPECT_EQ(map, read_file(dir + "/t2.csv"));
  EXPECT_EQ(map.substr(0, map.find('\n')), "disorder,q,xi,realization,mode,freq_khz,ipr");
  EXPECT_EQ(std::count(map.begin(), map.end(), '\n'), 1 + 3 * 4);
  ASSERT_EQ(run_tool("spectrum",
                     "--disorder RDM1 --N 3000 --xi 0.5 --q 0.5 --realization 2 --near 15 --count 4 "
                     "--method bisect --output " +
                         dir + "/s.csv")
                .exit_code,
            0);
  std::istringstream rows(map), spectrum(read_file(dir + "/s.csv"));
  std::string row, line;
  std::getline(spectrum, line);
  int matched = 0;
  while (std::getline(rows, row))
    if (row.rfind("RDM1,0.5,0.5,2,", 0) == 0 && std::getline(spectrum, line)) {
      EXPECT_EQ(row.substr(std::string("RDM1,0.5,0.5,2,").size()), line);
      ++matched;
    }
  EXPECT_EQ(matched, 4);
  EXPECT_EQ(run_tool("ipr-map", "--N 50 --near 15 --count 3 --method slepc --output " + dir + "/x.csv").exit_code, 2);
  EXPECT_EQ(run_tool("ipr-map", "--N 50 --method bisect --output " + dir + "/x.csv").exit_code, 2);
  std::filesystem::remove_all(dir);
}

// Every mode of a long chain in O(N) memory: the fast solver once held an N x N block per thread
// (512 MB here, 80 GB at N = 1e5: std::bad_alloc); only a degenerate cluster's vectors now.
TEST(IprMapTool, EveryModeOfALongChainNeedsMemoryOfOrderN) {
  const std::string dir = scratch_folder("ipr-memory");
  const std::string command = "cd '" + dir + "' && /usr/bin/time -f %M -o rss.txt '" + tool_path("ipr-map") +
                              "' --N 8000 --xi 0.5 --q 0.5 --realizations 1 --threads 1 --quiet 2>/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const long kilobytes = std::stol(read_file(dir + "/rss.txt"));
  EXPECT_LT(kilobytes, 100 * 1024) << "peak memory " << kilobytes << " kB; N x N doubles are 500,000 kB";
}

// Eigenvectors of every mode (--solver lapack) do need N x N per thread: refused up front, naming
// the memory and what fits, as the spectrum tool does.
TEST(IprMapTool, EveryModeWithEigenvectorsBeyondMemoryIsRefusedSayingWhatFits) {
  const std::string dir = scratch_folder("ipr-too-large");
  const ToolResult r = run_tool_in(dir, "ipr-map", "--N 100000 --solver lapack --xi 0.5 --q 0.5 --output big");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("ipr-map: error: --N 100000: every mode with eigenvectors (method lapack) needs 160 GB", 0), 0u)
      << r.err;
  EXPECT_NE(r.err.find("what fits: the fast solver (every IPR in O(N) memory) or selected modes (--near and "
                       "--count, or --window)"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace granular::testing
