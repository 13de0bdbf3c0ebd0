// Flat and sphere walls of a chain recipe (model/chain_recipe.hpp: WallShape).
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/chain_recipe.hpp"

namespace granular {
namespace {

ChainRecipe homogeneous_recipe(std::size_t n, WallShape walls) {
  return {.source = TwoTypeDraw{.disorder = Disorder::homogeneous}, .N = n, .F0 = 10, .walls = walls};
}

// The textbook fixed-end lattice: N equal masses m, N+1 equal springs B, both ends fixed,
// ω_j = 2 √(B/m) sin(jπ / (2(N+1))).
std::vector<double> lattice_khz(const Chain& bulk_reference, std::size_t n) {
  const double b = linear_stiffness(bulk_reference.contact[1], bulk_reference.precompression);
  const double m = bulk_reference.mass[0];
  std::vector<double> f(n);
  for (std::size_t j = 1; j <= n; ++j)
    f[j - 1] = 2 * std::sqrt(b / m) *
               std::sin(static_cast<double>(j) * std::numbers::pi / (2.0 * static_cast<double>(n + 1))) /
               (2 * std::numbers::pi) / 1e3;
  return f;
}

TEST(WallShape, SphereWallsMakeTheHomogeneousChainTheTextbookLattice) {
  const std::size_t n = 100;
  const Chain chain = homogeneous_recipe(n, WallShape::sphere).chain(0);
  EXPECT_DOUBLE_EQ(chain.contact.front(), chain.contact[1]);
  EXPECT_DOUBLE_EQ(chain.contact.back(), chain.contact[1]);
  const Spectrum s = spectrum(dynamical_matrix(chain));
  const std::vector<double> exact = lattice_khz(chain, n);
  ASSERT_EQ(s.freq_khz.size(), n);
  for (std::size_t j = 0; j < n; ++j) EXPECT_NEAR(s.freq_khz[j], exact[j], 1e-12 * exact[j]) << "mode " << j + 1;
}

TEST(WallShape, FlatWallsShiftTheLowestModeOfTheLattice) {
  // A flat wall's bond is stiffer than a bulk bond (twice the effective radius): mode 1 of
  // N = 100 lies ~0.4 % above the lattice's, which is why a textbook check needs sphere walls.
  const std::size_t n = 100;
  const Chain flat = homogeneous_recipe(n, WallShape::flat).chain(0);
  const double exact = lattice_khz(flat, n)[0];
  const double shift = spectrum(dynamical_matrix(flat)).freq_khz[0] / exact - 1;
  EXPECT_GT(shift, 0.002);
  EXPECT_LT(shift, 0.006);
}

TEST(WallShape, EveryRecipeKindTakesSphereWallsFromItsEndBeads) {
  ChainRecipe types = homogeneous_recipe(6, WallShape::sphere);
  types.source = GivenTypes{.types = {2, 1, 1, 2, 1, 1}};
  ChainRecipe radii = homogeneous_recipe(3, WallShape::sphere);
  radii.source = GivenRadii{.radii = {3e-3, 4e-3, 5e-3}};
  ChainRecipe drawn{.source = TwoTypeDraw{.disorder = Disorder::anderson, .q = 0.5},
                    .N = 40,
                    .walls = WallShape::sphere,
                    .seed = 4};
  for (const ChainRecipe* r : {&types, &radii, &drawn}) {
    const Chain c = r->chain(2);
    const std::size_t n = c.size();
    EXPECT_DOUBLE_EQ(c.contact[0], hertz_coefficient(r->material, c.radius[0], r->material, c.radius[0]));
    EXPECT_DOUBLE_EQ(c.contact[n], hertz_coefficient(r->material, c.radius[n - 1], r->material, c.radius[n - 1]));
    // The bead source (transfer matrices) sees the same end bonds as the stored chain.
    std::vector<double> mass(n), stiffness(n + 1);
    r->beads(2)->read(0, n, mass.data(), stiffness.data());
    EXPECT_DOUBLE_EQ(stiffness[0], linear_stiffness(c.contact[0], c.precompression));
    EXPECT_DOUBLE_EQ(stiffness[n], linear_stiffness(c.contact[n], c.precompression));
  }
}

TEST(WallShape, DescriptionsRoundTripAndBadWordsNameWalls) {
  ChainRecipe r{.source = TwoTypeDraw{.disorder = Disorder::rdm2, .q = 0.3},
                .N = 50,
                .walls = WallShape::sphere,
                .seed = 9};
  nlohmann::json fields;
  describe_fields(r, fields);
  EXPECT_EQ(fields["walls"], walls_description(WallShape::sphere));
  EXPECT_EQ(parse_recipe_fields(fields).walls, WallShape::sphere);
  EXPECT_EQ(parse_recipe_fields(fields).chain(1).contact, r.chain(1).contact);
  fields["walls"] = "padded";
  EXPECT_THROW(parse_recipe_fields(fields), InvalidInput);
  EXPECT_EQ(parse_wall_shape("flat"), WallShape::flat);
  try {
    parse_wall_shape("round");
    FAIL() << "accepted 'round'";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "walls");
  }
}

}  // namespace
}  // namespace granular
