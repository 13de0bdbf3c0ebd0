// The crystal IPR map: every mode counted once, the undisordered cell equal to the perfect
// crystal's binned IPRs, reproducible, and localization at the top of the band under strong mass
// disorder (docs/crystals.md, "The IPR map").
#include "granular/study/crystal_ipr_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "granular/crystal/crystal_matrix.hpp"
#include "granular/crystal/crystal_spectrum.hpp"
#include "granular/crystal/static_state.hpp"
#include "granular/error.hpp"

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

TEST(CrystalIprMap, IsBitIdenticalOnTwoThreadsAndLocalizesTheTopOfTheBand) {
  CrystalIprMapConfig c = crystal_map_config();
  const auto a = crystal_ipr_map(c);
  c.threads = 2;
  const auto b = crystal_ipr_map(c);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].bin_modes, b[k].bin_modes);
    EXPECT_EQ(a[k].bin_ratios, b[k].bin_ratios);
    for (std::size_t j = 0; j < a[k].bin_ipr.size(); ++j) {
      EXPECT_TRUE(crystal_map_same(a[k].bin_ipr[j], b[k].bin_ipr[j])) << "bin " << j;
      EXPECT_TRUE(crystal_map_same(a[k].bin_ratio[j], b[k].bin_ratio[j])) << "bin " << j;
    }
  }
  // Light beads (density down to 0.1 ρ) push modes above the perfect band and hold them: the top
  // bins' mean IPR is ~100/N against ≤ 2.2/N for every bin of the perfect crystal.
  EXPECT_GT(crystal_map_max(a[1].bin_ipr), 10 * crystal_map_max(a[0].bin_ipr));
  EXPECT_GT(a[1].bin_modes.size(), a[0].bin_modes.size());
}

TEST(CrystalIprMap, RefusesBadWidthsRealizationsAndBins) {
  CrystalIprMapConfig c = crystal_map_config();
  c.widths = {1.0};
  EXPECT_THROW(crystal_ipr_map(c), InvalidInput);
  c = crystal_map_config(), c.realizations = 0;
  EXPECT_THROW(crystal_ipr_map(c), InvalidInput);
  c = crystal_map_config(), c.bin_hz = 0;
  EXPECT_THROW(crystal_ipr_map(c), InvalidInput);
  c = crystal_map_config(), c.threads = -1;
  EXPECT_THROW(crystal_ipr_map(c), InvalidInput);
  c = crystal_map_config(), c.crystal.packing.Lx = 1;
  try {
    crystal_ipr_map(c);
    ADD_FAILURE() << "Lx 1 accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "Lx");
  }
}

}  // namespace
}  // namespace granular
