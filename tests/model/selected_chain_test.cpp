// A realization made ready for a run: stored and streamed, it is the recipe's chain bead for bead,
// described as describe() says, warned about in the caller's names, and refused past its size.
#include "granular/model/selected_chain.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "granular/error.hpp"

namespace granular {
namespace {

ChainRecipe anderson(std::size_t n) {
  ChainRecipe r;
  r.N = n, r.draw().q = 0.3, r.draw().xi = 0.6, r.seed = 7;
  return r;
}

TEST(SelectedChain, IsTheRecipesRealizationDescribed) {
  const ChainRecipe recipe = anderson(301);
  const SelectedChain s = select_chain(recipe, 4, {"R1", "beads", "radii"});
  const Chain direct = recipe.chain(4);
  EXPECT_EQ(s.chain.radius, direct.radius);
  EXPECT_EQ(s.chain.contact, direct.contact);
  EXPECT_EQ(s.description, describe(recipe, 4));
  EXPECT_EQ(s.realization, 4u);
  EXPECT_TRUE(s.warnings.empty());
  EXPECT_NE(select_chain(recipe, 5, {"R1", "beads", "radii"}).chain.radius, direct.radius);
}

TEST(SelectedChain, StreamedBeadsEqualTheStoredChain) {
  const ChainRecipe recipe = anderson(1001);
  const StreamedChain s = stream_chain(recipe, 2, {"R1", "beads", "radii"});
  const Chain stored = recipe.chain(2);
  const std::vector<double> stiffness = linear_stiffness(stored);
  ASSERT_EQ(s.beads->size(), stored.size());
  std::vector<double> mass(stored.size()), bond(stored.size() + 1);
  s.beads->read(0, stored.size(), mass.data(), bond.data());
  for (std::size_t n = 0; n < stored.size(); ++n) EXPECT_DOUBLE_EQ(mass[n], stored.mass[n]) << n;
  for (std::size_t k = 0; k < bond.size(); ++k) EXPECT_DOUBLE_EQ(bond[k], stiffness[k]) << k;
  EXPECT_EQ(s.description, describe(recipe, 2));
  EXPECT_EQ(s.highest_frequency_khz, highest_frequency_bound_khz(recipe));
}

TEST(SelectedChain, WarnsInTheCallersNames) {
  ChainRecipe slip = anderson(50);
  slip.R1 = 4.76;  // millimetres typed as metres
  const SelectedChain s = select_chain(slip, 0, {"--R1", "--types", "--radii"});
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0].rfind("--R1: radius 4.76 m", 0), 0u) << s.warnings[0];
  EXPECT_EQ(stream_chain(slip, 0, {"R1", "beads", "radii"}).warnings[0].rfind("R1: radius 4.76 m", 0), 0u);
}

TEST(SelectedChain, AStoredChainStopsAt1e8AStreamedDrawAt1e12) {
  ChainRecipe big = anderson(200000000);
  try {
    select_chain(big, 0, {"R1", "beads", "radii"});
    FAIL() << "a stored chain of 2e8 beads was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "N");
  }
  EXPECT_EQ(stream_chain(big, 0, {"R1", "beads", "radii"}).beads->size(), 200000000u);  // drawn in pieces
  big.N = 2000000000000;
  EXPECT_THROW(stream_chain(big, 0, {"R1", "beads", "radii"}), InvalidInput);
  big.N = 200000000;
  big.walls = WallShape::sphere;  // stored: the 1e8 limit again
  EXPECT_THROW(stream_chain(big, 0, {"R1", "beads", "radii"}), InvalidInput);
}

}  // namespace
}  // namespace granular
