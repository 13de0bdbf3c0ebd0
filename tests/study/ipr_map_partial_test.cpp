// ipr-map with a partial selection (--near/--count or --window): the rows are the selected modes
// of every realization, the same as spectrum() on that chain, for any thread count.
#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/study/ipr_map.hpp"

namespace granular {
namespace {

IprMapConfig small_config() {
  IprMapConfig c;
  c.chain.draw().disorder = Disorder::rdm1;
  c.q_values = {0.5};
  c.xi_values = {0.5, 0.8};
  c.chain.N = 400;
  c.realizations = 3;
  c.chain.seed = 5;
  return c;
}

TEST(IprMapPartial, RowsAreThePartialSpectraOfEachRealization) {
  IprMapConfig c = small_config();
  c.selection = nearest(15.0, 6);
  for (SpectrumMethod m : {SpectrumMethod::lapack, SpectrumMethod::bisect, SpectrumMethod::arpack}) {
    c.spectrum.method = m;
    const auto cells = compute_ipr_map(c, {.threads = 2});
    ASSERT_EQ(cells.size(), 2u);
    for (const auto& cell : cells) {
      ASSERT_EQ(cell.ipr.size(), 18u);
      ASSERT_EQ(cell.mode.size(), 18u);
      for (std::size_t r = 0; r < 3; ++r) {
        const Chain chain = rdm1({.N = c.chain.N, .q = 0.5, .xi = cell.xi, .seed = c.chain.seed, .realization = r});
        const Spectrum p = spectrum(dynamical_matrix(chain), c.selection, {.method = m});
        for (std::size_t j = 0; j < 6; ++j) {
          EXPECT_EQ(cell.realization[6 * r + j], r);
          EXPECT_EQ(cell.mode[6 * r + j], p.mode[j]);
          EXPECT_EQ(cell.ipr[6 * r + j], p.ipr[j]);  // same computation, bit for bit
          EXPECT_EQ(cell.freq_khz[6 * r + j], p.freq_khz[j]);
        }
      }
    }
    const auto serial = compute_ipr_map(c, {.threads = 1});
    for (std::size_t i = 0; i < cells.size(); ++i) EXPECT_EQ(serial[i].ipr, cells[i].ipr);
  }
}

TEST(IprMapPartial, WindowsPoolModesAndTheFullPathIsUnchanged) {
  IprMapConfig c = small_config();
  c.selection = window(20.0, 25.0);
  c.spectrum.method = SpectrumMethod::lapack;
  const auto cells = compute_ipr_map(c);
  for (const auto& cell : cells) {
    EXPECT_EQ(cell.mode.size(), cell.ipr.size());
    for (double f : cell.freq_khz) {
      EXPECT_GE(f, 20.0);
      EXPECT_LE(f, 25.0);
    }
  }
  c.selection = nearest(15.0, 401);
  EXPECT_THROW(compute_ipr_map(c), InvalidInput);
  c.selection = all_modes();
  c.spectrum.method = SpectrumMethod::fast;
  const auto full = compute_ipr_map(c);
  ASSERT_EQ(full.size(), 2u);
  EXPECT_EQ(full[0].ipr.size(), 400u);
  EXPECT_TRUE(full[0].mode.empty());
}

}  // namespace
}  // namespace granular
