// The JSON beside a run's outputs: written before they are committed, with what reproduces the run.
#include "granular/io/run_metadata.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "granular/code_identity.hpp"
#include "granular/error.hpp"
#include "granular/io/hdf5_file.hpp"
#include "scratch.hpp"

namespace granular {
namespace {

TEST(RunMetadata, WritesTheRunThenCommitsItsOutputs) {
  const std::string csv_path = testing::scratch_path("run_metadata_test", "run.csv");
  const std::string json_path = testing::scratch_path("run_metadata_test", "run.json");
  std::filesystem::remove(csv_path);
  RunMetadata meta("spectrum", "spectrum --output 'my run'", true);
  EXPECT_EQ(meta.command(), "spectrum --output 'my run'");
  meta["output"] = csv_path;
  meta.merge({{"parameters", {{"N", 10}}}, {"output", "replaced.csv"}});
  AtomicFile csv(csv_path);
  csv.stream() << "a\n1\n";
  meta.write(json_path, {&csv});
  EXPECT_TRUE(std::filesystem::exists(csv_path));
  std::ifstream in(json_path);
  const nlohmann::json json = nlohmann::json::parse(in);
  EXPECT_EQ(json.at("tool"), "spectrum");
  EXPECT_EQ(json.at("version"), code_version());
  EXPECT_EQ(json.at("commit"), code_commit());
  // The BLAS is traced to a file that exists (whichever library the alternatives picked).
  const std::string blas = json.at("blas");
  const auto file = blas.find(": /");
  EXPECT_TRUE(std::filesystem::exists(blas.substr(file == std::string::npos ? 0 : file + 2))) << blas;
  EXPECT_EQ(json.at("command"), "spectrum --output 'my run'");
  EXPECT_EQ(json.at("output"), "replaced.csv");
  EXPECT_EQ(json.at("parameters").at("N"), 10);
  EXPECT_GE(json.at("wall_time_s").get<double>(), 0);
  EXPECT_EQ(json.at("started_utc").get<std::string>().size(), 20u);  // 2026-11-26T08:50:37Z
}

// Text and HDF5 outputs are committed alike, after the JSON; when the JSON cannot be written,
// neither appears (the job's files: the metadata first, never an output without it).
TEST(RunMetadata, CommitsTextAndHdf5OutputsOnlyAfterTheJson) {
  const std::string csv_path = testing::scratch_path("run_metadata_test", "both.csv");
  const std::string h5_path = testing::scratch_path("run_metadata_test", "both.h5");
  const std::string json_path = testing::scratch_path("run_metadata_test", "both.json");
  const std::string unwritable = testing::scratch_path("run_metadata_test", "no-such-folder/both.json");
  for (const auto& p : {csv_path, h5_path, json_path}) std::filesystem::remove(p);
  {
    RunMetadata meta("breathers", "breathers", true);
    AtomicFile csv(csv_path);
    csv.stream() << "a\n1\n";
    Hdf5File h5(h5_path);
    h5.write("x", std::vector<double>{1, 2});
    EXPECT_THROW(meta.write(unwritable, {&csv, &h5}), IoError);
  }
  EXPECT_FALSE(std::filesystem::exists(csv_path));
  EXPECT_FALSE(std::filesystem::exists(h5_path));

  RunMetadata meta("breathers", "breathers", true);
  AtomicFile csv(csv_path);
  csv.stream() << "a\n1\n";
  Hdf5File h5(h5_path);
  h5.write("x", std::vector<double>{1, 2});
  meta.write(json_path, {&csv, &h5});
  EXPECT_TRUE(std::filesystem::exists(json_path));
  EXPECT_TRUE(std::filesystem::exists(csv_path));
  EXPECT_TRUE(std::filesystem::exists(h5_path));
}

}  // namespace
}  // namespace granular
