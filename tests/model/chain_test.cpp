#include "granular/model/chain.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "fixtures.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

TEST(Chain, MassesMatchSpec) {
  const Chain c = make_chain({fixtures::r1, fixtures::r1 / 2}, 10);
  const auto m1 = fixtures::reference("m1"), m2 = fixtures::reference("m2");
  EXPECT_NEAR(c.mass[0], m1.value, m1.tolerance);
  EXPECT_NEAR(c.mass[1], m2.value, m2.tolerance);
  EXPECT_DOUBLE_EQ(c.inverse_mass[1], 1 / c.mass[1]);
}

TEST(Chain, StaticOverlapBalancesPrecompression) {
  const Chain c = fixtures::random_chain(Disorder::anderson, 50, 0.3, 0.5, 3, 0.7);
  ASSERT_EQ(c.bonds(), 51u);
  for (std::size_t k = 0; k < c.bonds(); ++k) EXPECT_NEAR(c.contact[k] * std::pow(c.overlap[k], 1.5), 0.7, 1e-13);
  const Chain vacuum = fixtures::homogeneous(5, 0);
  for (double d : vacuum.overlap) EXPECT_EQ(d, 0.0);
}

TEST(Chain, WallBondsUseSphereWallContact) {
  const Chain c = fixtures::homogeneous(4);
  EXPECT_NEAR(c.contact.front(), fixtures::reference("A_wall_R1").value, fixtures::reference("A_wall_R1").tolerance);
  EXPECT_DOUBLE_EQ(c.contact.front(), c.contact.back());
  const Chain bulk = fixtures::homogeneous_bulk_walls(4);
  EXPECT_DOUBLE_EQ(bulk.contact.front(), bulk.contact[2]);
}

TEST(Chain, RejectsInvalidSpecs) {
  EXPECT_THROW(make_chain({fixtures::r1}, 10), InvalidInput);
  EXPECT_THROW(make_chain({fixtures::r1, fixtures::r1}, -1), InvalidInput);
  EXPECT_THROW(make_chain({fixtures::r1, fixtures::r1}, std::numeric_limits<double>::quiet_NaN()), InvalidInput);
  EXPECT_THROW(make_chain({fixtures::r1, 0.0}, 10), InvalidInput);
  EXPECT_THROW(make_chain({fixtures::r1, std::numeric_limits<double>::infinity()}, 10), InvalidInput);
  EXPECT_THROW(make_chain({fixtures::r1, fixtures::r1}, 10, Material{-1, 0.3, 8000}), InvalidInput);
  EXPECT_THROW(make_chain({fixtures::r1, fixtures::r1}, 10, Material{1e9, 0.5, 8000}), InvalidInput);
}

}  // namespace
}  // namespace granular
