// The files of the spreading and exponent studies: one writer each, every path named before the
// run, the CSVs and the HDF5 energy map left uncommitted until the JSON is written.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "granular/files/exponent_files.hpp"
#include "granular/files/spreading_files.hpp"
#include "scratch.hpp"

namespace granular {
namespace {

std::string scratch(const std::string& name) { return testing::scratch_path("tool_files_test", name); }

TEST(SpreadingFiles, PathsUnderThePrefixAndTheUsersOwn) {
  SpreadingPaths one = spreading_paths("run", false, false, false);
  EXPECT_EQ(one.all(), (std::vector<std::string>{"run.csv", "run.json", "", "", "", "", "", "", "", "", "", ""}));
  SpreadingPaths all = spreading_paths("d/run", true, true, true, true, true);
  all.final_state = "final.csv";
  EXPECT_EQ(all.all(), (std::vector<std::string>{"d/run.csv", "d/run.json", "final.csv", "", "", "d/run-profile.csv",
                                                 "d/run-forces.csv", "d/run-sem.csv", "d/run.checkpoint", "",
                                                 "d/run-lyapunov.csv", "d/run-clv.h5"}));
}

TEST(SpreadingFiles, WritesTheRunsFilesUncommittedUntilTold) {
  TransportCase c;
  c.chain.N = 21;
  c.site = 11;
  c.dynamics.integration.duration = 2e-5;
  c.dynamics.spread.samples = 5;
  c.fit = false;
  c.dynamics.forces.sites = {3};
  c.dynamics.energy_map = EnergyMapObserver::Settings{.samples = 5};
  const Chain chain = c.chain.chain(0);
  const SpreadingResult run = run_spreading(chain, kick(c, chain).initial, spreading_config(c));
  SpreadingPaths paths = spreading_paths(scratch("one"), false, true, true);
  paths.final_state = scratch("one-final.csv");
  paths.energy_map = scratch("one-map.h5");
  for (const auto& p : paths.all())
    if (!p.empty()) std::filesystem::remove(p);
  auto files = write_spreading_files(paths, run, nullptr, c.dynamics);
  ASSERT_EQ(files.text.size(), 4u);  // curves, profile, forces, final state
  ASSERT_TRUE(files.energy_map);
  EXPECT_FALSE(std::filesystem::exists(paths.csv));
  EXPECT_FALSE(std::filesystem::exists(paths.energy_map));  // the map too waits for the JSON
  files.commit();
  EXPECT_TRUE(std::filesystem::exists(paths.energy_map));
  std::ostringstream expected;
  write_spreading_csv(expected, run);
  std::ifstream in(paths.csv);
  std::stringstream got;
  got << in.rdbuf();
  EXPECT_EQ(got.str(), expected.str());
  EXPECT_TRUE(std::filesystem::exists(paths.final_state));
  std::vector<std::string> said = warnings(run, c.dynamics);
  for (const auto& note : notes(c)) said.push_back(note);
  EXPECT_EQ(spreading_notes(c, run, nullptr), said);
}

TEST(SpreadingFiles, ExponentEntriesAreNullWhenNoneWereFitted) {
  const nlohmann::json none = describe_exponents(std::nullopt, SpreadCentre::site);
  for (const char* key : {"gamma", "gamma_err", "gamma_real_err", "eta", "eta_err", "eta_real_err", "power_law"}) {
    ASSERT_TRUE(none.contains(key)) << key;
    EXPECT_TRUE(none.at(key).is_null()) << key;
  }
  EXPECT_FALSE(none.contains("exponents"));
}

TEST(SpreadingFiles, EnsembleAndSpectralDensityEntries) {
  TransportSummary s;
  s.realizations = 9, s.max_energy_error = 2.5e-7, s.reached_walls = 1, s.excluded = {3};
  const nlohmann::json ensemble = describe_ensemble(s, 4);
  EXPECT_EQ(ensemble, (nlohmann::json{{"realizations", 9},
                                      {"threads", 4},
                                      {"mpi_ranks", 1},
                                      {"max_energy_error", 2.5e-7},
                                      {"reached_walls", 1},
                                      {"failed_excluded", nlohmann::json::array({3})}}));
  const SpectralDensityObserver::Settings g{.samples = 300, .source = SpectrumSource::velocity};
  EXPECT_EQ(describe_spectral_density(g), (nlohmann::json{{"of", "velocity"}, {"samples", 300}}));
}

TEST(ExponentFiles, TableParametersAsListed) {
  ExponentTableConfig config;
  config.precompressions = {10, 0.1};
  config.chains.clear();
  config.kicks = {Kick::displacement, Kick::mode};
  EXPECT_EQ(describe_table_parameters(config, 2),
            (nlohmann::json{
                {"chains", "none"}, {"F0", {10, 0.1}}, {"ic", "displacement,mode"}, {"threads", 2}, {"mpi_ranks", 1}}));
}

TEST(ExponentFiles, PathsAndCases) {
  const ExponentPaths plain = exponent_paths("ex", false), paper = exponent_paths("ex", true);
  EXPECT_EQ(plain.all(), (std::vector<std::string>{"ex.csv", "ex-curves.csv", "ex-profiles.csv", "ex.json"}));
  EXPECT_EQ(paper.all().back(), "ex-paper.csv");
  EXPECT_EQ(case_checkpoints("ex.checkpoint", 3),
            (std::vector<std::string>{"ex.checkpoint.0", "ex.checkpoint.1", "ex.checkpoint.2"}));
  ExponentCell cell;
  cell.summary.excluded = {4, 7};
  const nlohmann::json cases = describe_cells({cell});
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_EQ(cases[0].at("failed_excluded"), nlohmann::json({4, 7}));
  EXPECT_EQ(cases[0].at("chain"), chain_name(cell));
  EXPECT_FALSE(cases[0].contains("exponents"));
  EXPECT_FALSE(cases[0].contains("mle_at_T"));
}

}  // namespace
}  // namespace granular
