// The dynamical matrix read a piece at a time from a bead source is the one built from the stored
// chain, bit for bit, for every kind of recipe (random draws stream; the rest walk their chain).
#include "granular/linear/dynamical_matrix.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "granular/io/bead_distribution_syntax.hpp"
#include "granular/model/chain_recipe.hpp"

namespace granular {
namespace {

void expect_same_matrix(const ChainRecipe& recipe, std::uint64_t r, const std::string& what) {
  const DynamicalMatrix stored = dynamical_matrix(recipe.chain(r));
  const DynamicalMatrix streamed = dynamical_matrix(*recipe.beads(r));
  EXPECT_EQ(streamed.diagonal, stored.diagonal) << what;
  EXPECT_EQ(streamed.off_diagonal, stored.off_diagonal) << what;
  EXPECT_EQ(streamed.inverse_sqrt_mass, stored.inverse_sqrt_mass) << what;
}

TEST(DynamicalMatrix, FromABeadSourceIsTheStoredChainsBitForBit) {
  for (Disorder d : {Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2}) {
    ChainRecipe r;
    r.draw().disorder = d, r.N = 150001, r.draw().q = 0.37, r.draw().xi = 0.55, r.seed = 11,
    r.F0 = 0.3;  // N past one piece
    expect_same_matrix(r, 3, "disorder " + to_string(d));
  }
  ChainRecipe types;
  types.N = 2001;
  types.source = parse_bead_types("0.004:0.3,0.003:0.5,0.002:0.2", false, Disorder::anderson, "beads");
  expect_same_matrix(types, 1, "k types");
  ChainRecipe sphere;
  sphere.N = 501, sphere.walls = WallShape::sphere;
  expect_same_matrix(sphere, 0, "sphere walls");
  ChainRecipe radii;
  radii.source = GivenRadii{.radii = {4e-3, 3e-3, 5e-3, 2.5e-3}};
  expect_same_matrix(radii, 0, "given radii");
  for (auto kind : {Quasiperiodic::Kind::s1, Quasiperiodic::Kind::s2, Quasiperiodic::Kind::cylinders}) {
    ChainRecipe q;
    q.N = 987;
    q.source = Quasiperiodic{.kind = kind, .modulation = 0.4};
    expect_same_matrix(q, 2, "quasiperiodic " + to_string(kind));  // s1: on-site springs
  }
}

}  // namespace
}  // namespace granular
