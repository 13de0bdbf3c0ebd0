// A long IPR map says how long it will take before it starts (study/ipr_map_estimate.hpp): one chain
// timed on its leading beads, scaled by the chains over the threads; short maps and selections
// are not timed.
#include <gtest/gtest.h>

#include "granular/study/ipr_map_estimate.hpp"

namespace granular {
namespace {

IprMapConfig estimated_map(std::size_t n, std::size_t realizations) {
  IprMapConfig c;
  c.chain.N = n;
  c.q_values = {0.5};
  c.xi_values = {0.5, 0.7};
  c.realizations = realizations;
  return c;
}

TEST(IprMapEstimate, ScalesOneChainByTheChainsOverTheThreads) {
  const IprMapEstimate e = estimate_ipr_map(estimated_map(8000, 3), 2);
  EXPECT_EQ(e.chains, 6u);
  EXPECT_EQ(e.chain.beads, 8000u);
  ASSERT_GT(e.chain.seconds, 0);
  EXPECT_DOUBLE_EQ(e.seconds, 3 * e.chain.seconds);  // 6 chains, 2 at a time
  EXPECT_TRUE(describe(e).starts_with("6 chains of 8000 beads, every mode: about ")) << describe(e);
  EXPECT_TRUE(describe(e).ends_with("; progress counts chains")) << describe(e);
}

TEST(IprMapEstimate, ShortMapsAndSelectionsAreNotTimed) {
  EXPECT_EQ(estimate_ipr_map(estimated_map(1000, 100), 1).seconds, 0);
  IprMapConfig selected = estimated_map(8000, 3);
  selected.selection = nearest(10, 3);
  EXPECT_EQ(estimate_ipr_map(selected, 1).seconds, 0);
}

}  // namespace
}  // namespace granular
