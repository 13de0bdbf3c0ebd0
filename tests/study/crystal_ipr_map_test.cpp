// The crystal IPR map: every mode counted once, the undisordered cell equal to the perfect
// crystal's binned IPRs, reproducible, and localization at the top of the band under strong mass
// disorder (docs/crystals.md, "The IPR map").
#include "granular/study/crystal_ipr_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include "granular/crystal/crystal_matrix.hpp"
#include "granular/crystal/crystal_spectrum.hpp"
#include "granular/crystal/packing.hpp"
#include "granular/crystal/static_state.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/error.hpp"
#include "granular/parameter_json.hpp"

namespace granular {
namespace {

CrystalIprMapConfig crystal_map_config() {
  CrystalIprMapConfig c;
  c.crystal.packing.lattice = Lattice::hexagonal, c.crystal.packing.Lx = 12, c.crystal.packing.Ly = 12;
  c.widths = {0.0, 0.9}, c.realizations = 4, c.bin_hz = 4000;
  return c;
}

// Equal to the bit, NaN (an empty bin) equal to NaN.
bool crystal_map_same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

double crystal_map_max(const std::vector<double>& v) {
  double m = 0;
  for (double x : v)
    if (!std::isnan(x)) m = std::max(m, x);
  return m;
}

TEST(CrystalIprMap, CountsEveryModeAndMatchesThePerfectCrystal) {
  const CrystalIprMapConfig c = crystal_map_config();
  const auto cells = crystal_ipr_map(c);
  ASSERT_EQ(cells.size(), 2u);
  for (const CrystalIprMapCell& cell : cells)
    EXPECT_EQ(std::accumulate(cell.bin_modes.begin(), cell.bin_modes.end(), std::size_t{0}), 2u * 144 * 4);

  const Packing p = make_packing(c.crystal.packing);
  const CrystalSpectrum s = crystal_spectrum(crystal_matrix(p, static_state(p)));
  const std::size_t bins = cells[0].bin_modes.size();
  std::vector<double> sum(bins, 0.0);
  std::vector<std::size_t> count(bins, 0);
  for (std::size_t k = 0; k < s.size(); ++k) {
    const auto b = static_cast<std::size_t>(std::max(0.0, s.freq_hz[k]) / c.bin_hz);
    ASSERT_LT(b, bins);
    sum[b] += s.ipr[k], ++count[b];
  }
  for (std::size_t b = 0; b < bins; ++b) {
    EXPECT_EQ(cells[0].bin_modes[b], 4 * count[b]) << "bin " << b;
    if (count[b] > 0) {
      EXPECT_NEAR(cells[0].bin_ipr[b], sum[b] / static_cast<double>(count[b]), 1e-12) << "bin " << b;
    }
  }
}

void expect_same_crystal_maps(const std::vector<CrystalIprMapCell>& a, const std::vector<CrystalIprMapCell>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].bin_modes, b[k].bin_modes);
    EXPECT_EQ(a[k].bin_ratios, b[k].bin_ratios);
    ASSERT_EQ(a[k].bin_ipr.size(), b[k].bin_ipr.size());
    for (std::size_t j = 0; j < a[k].bin_ipr.size(); ++j) {
      EXPECT_TRUE(crystal_map_same(a[k].bin_ipr[j], b[k].bin_ipr[j])) << "bin " << j;
      EXPECT_TRUE(crystal_map_same(a[k].bin_ratio[j], b[k].bin_ratio[j])) << "bin " << j;
    }
  }
}

TEST(CrystalIprMap, IsBitIdenticalOnTwoThreadsAndLocalizesTheTopOfTheBand) {
  const CrystalIprMapConfig c = crystal_map_config();
  const auto a = crystal_ipr_map(c, {.threads = 1});
  expect_same_crystal_maps(a, crystal_ipr_map(c, {.threads = 2}));
  // Light beads (density down to 0.1 ρ) push modes above the perfect band and hold them: the top
  // bins' mean IPR is ~100/N against ≤ 2.2/N for every bin of the perfect crystal.
  EXPECT_GT(crystal_map_max(a[1].bin_ipr), 10 * crystal_map_max(a[0].bin_ipr));
  EXPECT_GT(a[1].bin_modes.size(), a[0].bin_modes.size());
}

// With `near`, each crystal's `count` modes nearest the target by ARPACK: the same modes, bins and
// IPRs as those picked from every mode (dense LAPACK) of the same crystals.
TEST(CrystalIprMap, NearestModesAreThoseOfTheDenseSpectrum) {
  CrystalIprMapConfig c = crystal_map_config();
  c.widths = {0.5}, c.realizations = 2, c.bin_hz = 1000;
  c.crystal.near = 10.0, c.crystal.count = 30;  // 10 kHz: inside the band (about 0.5 ... 20 kHz)
  const auto cells = crystal_ipr_map(c, {.threads = 1});
  ASSERT_EQ(cells.size(), 1u);
  const std::size_t bins = cells[0].bin_modes.size();
  std::vector<double> sum(bins, 0.0);
  std::vector<std::size_t> count(bins, 0);
  const double sigma = std::pow(2 * std::acos(-1.0) * 10e3, 2);
  for (std::uint64_t r = 0; r < c.realizations; ++r) {
    const Packing p =
        make_packing(disordered(c.crystal.packing, {c.crystal.disorder.kind, 0.5, c.crystal.disorder.seed, r}));
    const CrystalSpectrum s = crystal_spectrum(crystal_matrix(p, static_state(p)));
    std::vector<std::size_t> order(s.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return std::fabs(s.omega2[a] - sigma) < std::fabs(s.omega2[b] - sigma);
    });
    for (std::size_t j = 0; j < 30; ++j) {
      const auto b = static_cast<std::size_t>(s.freq_hz[order[j]] / c.bin_hz);
      ASSERT_LT(b, bins);
      sum[b] += s.ipr[order[j]], ++count[b];
    }
  }
  for (std::size_t b = 0; b < bins; ++b) {
    EXPECT_EQ(cells[0].bin_modes[b], count[b]) << "bin " << b;
    if (count[b] > 0) {
      EXPECT_NEAR(cells[0].bin_ipr[b], sum[b] / static_cast<double>(count[b]), 1e-10) << "bin " << b;
    }
  }
  // ARPACK keeps its state in Fortran SAVE variables: the threads' solves take turns (they crashed in malloc).
  c.realizations = 16;
  expect_same_crystal_maps(crystal_ipr_map(c, {.threads = 1}), crystal_ipr_map(c, {.threads = 2}));
  c.crystal.disorder.seed = 5;  // a seed goes with the map's widths, not the crystal's own width
  EXPECT_NO_THROW(validate(c));
  c.crystal.near.reset(), c.crystal.count = 12;
  EXPECT_THROW(validate(c), InvalidInput);           // count without near
  c.crystal.near = 10.0, c.crystal.count = 2 * 144;  // every degree of freedom: not for a Krylov method
  try {
    crystal_ipr_map(c);
    ADD_FAILURE() << "count 2N accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "count");
  }
}

TEST(CrystalIprMap, RefusesBadWidthsRealizationsAndBins) {
  CrystalIprMapConfig c = crystal_map_config();
  c.widths = {1.0};
  EXPECT_THROW(crystal_ipr_map(c), InvalidInput);
  c = crystal_map_config(), c.realizations = 0;
  EXPECT_THROW(crystal_ipr_map(c), InvalidInput);
  c = crystal_map_config(), c.bin_hz = 0;
  EXPECT_THROW(crystal_ipr_map(c), InvalidInput);
  c = crystal_map_config();
  EXPECT_THROW(crystal_ipr_map(c, {.threads = -1}), InvalidInput);
  try {
    crystal_ipr_map(c, {.skip_failed = true});
    ADD_FAILURE() << "skip_failed accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "skip_failed");
  }
  c = crystal_map_config(), c.crystal.packing.Lx = 1;
  try {
    crystal_ipr_map(c);
    ADD_FAILURE() << "Lx 1 accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "Lx");
  }
}

// Stopped after some crystals (Ctrl-C in Python, SIGINT in the tool), then resumed: the crystals
// already solved come from the checkpoint, and the map is the uninterrupted one to the bit.
TEST(CrystalIprMap, ResumesAnInterruptedMapToTheUninterruptedOne) {
  CrystalIprMapConfig c = crystal_map_config();
  c.crystal.packing.Lx = 8, c.crystal.packing.Ly = 8, c.realizations = 5;
  const auto whole = crystal_ipr_map(c, {.threads = 2});
  const std::string log = (std::filesystem::temp_directory_path() / "granular-crystal-map.checkpoint").string();
  CheckpointLog::remove_all(log);
  std::atomic<int> started{0};
  RunOptions run{.threads = 2, .checkpoint = log};
  run.cancelled = [&] { return started++ >= 4; };
  EXPECT_THROW(crystal_ipr_map(c, run), Cancelled);
  const std::size_t kept = CheckpointLog::load(log, describe_rows(c, crystal_ipr_map_parameters()).dump()).size();
  EXPECT_GE(kept, 4u);
  EXPECT_LT(kept, 10u);
  run.cancelled = nullptr;
  try {  // not resuming: refused, the finished crystals kept
    crystal_ipr_map(c, run);
    ADD_FAILURE() << "a map not resuming wrote over an interrupted map's checkpoint";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "checkpoint");
  }
  run.resume = true;
  expect_same_crystal_maps(whole, crystal_ipr_map(c, run));
  CheckpointLog::remove_all(log);
}

}  // namespace
}  // namespace granular
