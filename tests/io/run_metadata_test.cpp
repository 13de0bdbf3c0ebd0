// The JSON beside a run's outputs: written before they are committed, with what reproduces the run.
#include "granular/io/run_metadata.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "granular/code_identity.hpp"
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
  EXPECT_EQ(json.at("command"), "spectrum --output 'my run'");
  EXPECT_EQ(json.at("output"), "replaced.csv");
  EXPECT_EQ(json.at("parameters").at("N"), 10);
  EXPECT_GE(json.at("wall_time_s").get<double>(), 0);
  EXPECT_EQ(json.at("started_utc").get<std::string>().size(), 20u);  // 2026-11-26T08:50:37Z
}

}  // namespace
}  // namespace granular
