// The IPR map averaged in frequency bins (IprMapConfig::bin_khz).
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "granular/linear/band_edges.hpp"
#include "granular/study/ipr_map.hpp"

namespace granular {
namespace {

// A map over the (q, ξ) grid of `disorder` chains of N beads, `realizations` each.
IprMapConfig bins_config(Disorder disorder, std::vector<double> q, std::vector<double> xi, std::size_t N,
                         std::size_t realizations) {
  IprMapConfig c;
  c.chain.draw().disorder = disorder;
  c.q_values = std::move(q);
  c.xi_values = std::move(xi);
  c.chain.N = N;
  c.realizations = realizations;
  return c;
}

// The periodic diatomic chain 1 2 1 2 … (RDM2 at q = 1: every dimer "1 2") has no bulk mode in
// the gap (fb1, fb2) of the infinite chain; frequency bins show that, where mode-number averaging
// of a disordered ensemble puts points in the gap. The finite chain between flat walls does have
// a wall (surface) mode in the gap (found here at 12.5–12.75 kHz, IPR ≈ 0.46, for N = 200,
// ξ = 0.5): physics, not a binning artefact. So: bins wholly inside the gap hold at most one
// mode per wall per realization, and only strongly localized ones (IPR > 0.2; the band modes of
// 200 beads have IPR ~ 1/100), every other gap bin is empty with IPR NaN.
TEST(IprMapBins, NoBulkModeInTheDiatomicGap) {
  IprMapConfig c = bins_config(Disorder::rdm2, {1.0}, {0.5}, 200, 2);
  c.bin_khz = 0.25;
  const auto cells = compute_ipr_map(c);
  ASSERT_EQ(cells.size(), 1u);
  const BandEdges e = band_edges(c.chain.material, c.chain.R1, 0.5, c.chain.F0);
  const double fb1 = e.fb1 / 1e3, fb2 = e.fb2 / 1e3;
  ASSERT_GT(fb2 - fb1, 4 * c.bin_khz);
  std::size_t inside = 0, total = 0, in_gap = 0;
  for (std::size_t b = 0; b < cells[0].bin_modes.size(); ++b) {
    total += cells[0].bin_modes[b];
    const double lo = static_cast<double>(b) * c.bin_khz, hi = lo + c.bin_khz;
    if (lo > fb1 && hi < fb2) {
      ++inside;
      in_gap += cells[0].bin_modes[b];
      if (cells[0].bin_modes[b] == 0) EXPECT_TRUE(std::isnan(cells[0].bin_ipr[b]));
      else
        EXPECT_GT(cells[0].bin_ipr[b], 0.2)
            << "bin [" << lo << ", " << hi << ") kHz in the gap (" << fb1 << ", " << fb2 << ") holds an extended mode";
    }
  }
  EXPECT_GT(inside, 50u);
  EXPECT_LE(in_gap, 2 * c.realizations) << "more gap modes than walls";
  EXPECT_EQ(total, c.chain.N * c.realizations) << "every mode of every realization is in one bin";
}

// Bins narrower than every level spacing hold one mode each (one realization): the binned mean
// is then that mode's IPR, bin by bin, exactly as the by-mode map gives it.
TEST(IprMapBins, OneModePerBinEqualsThePerModeMean) {
  IprMapConfig c = bins_config(Disorder::anderson, {0.5}, {0.6}, 60, 1);
  const auto by_mode = compute_ipr_map(c);
  const auto& f = by_mode[0].freq_khz;
  double spacing = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < f.size(); ++k) spacing = std::min(spacing, f[k] - f[k - 1]);
  ASSERT_GT(spacing, 0);
  c.bin_khz = spacing / 2;
  const auto binned = compute_ipr_map(c);
  std::size_t matched = 0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    const auto b = static_cast<std::size_t>(std::floor(f[k] / c.bin_khz));
    ASSERT_LT(b, binned[0].bin_modes.size());
    EXPECT_EQ(binned[0].bin_modes[b], 1u) << "mode " << k + 1;
    EXPECT_EQ(binned[0].bin_ipr[b], by_mode[0].ipr[k]) << "mode " << k + 1;
    ++matched;
  }
  std::size_t occupied = 0;
  for (std::size_t m : binned[0].bin_modes) occupied += m;
  EXPECT_EQ(occupied, c.chain.N);
  EXPECT_EQ(matched, c.chain.N);
}

TEST(IprMapBins, IdenticalForOneAndTwoThreads) {
  IprMapConfig c = bins_config(Disorder::rdm1, {0.3, 0.7}, {0.4, 0.9}, 80, 9);
  c.bin_khz = 0.5;
  const auto one = compute_ipr_map(c, {.threads = 1});
  const auto two = compute_ipr_map(c, {.threads = 2});
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].bin_modes, two[i].bin_modes);
    ASSERT_EQ(one[i].bin_ipr.size(), two[i].bin_ipr.size());
    for (std::size_t b = 0; b < one[i].bin_ipr.size(); ++b)
      EXPECT_TRUE(one[i].bin_ipr[b] == two[i].bin_ipr[b] ||
                  (std::isnan(one[i].bin_ipr[b]) && std::isnan(two[i].bin_ipr[b])));
  }
}

TEST(IprMapBins, RejectsBadBinWidth) {
  IprMapConfig c;
  c.xi_values = {0.5};
  c.bin_khz = -1;
  EXPECT_THROW(validate(c), InvalidInput);
  c.bin_khz = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(validate(c), InvalidInput);
  c.bin_khz = 1;
  c.selection = window(1, 2);
  c.spectrum.method = SpectrumMethod::lapack;
  EXPECT_THROW(validate(c), InvalidInput);
}

}  // namespace
}  // namespace granular
