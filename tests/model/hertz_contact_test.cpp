#include "granular/model/contact_law.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "fixtures.hpp"
#include "granular/error.hpp"
#include "granular/model/chain.hpp"

namespace granular {
namespace {

using fixtures::r1;

// The hand computation of docs/physics.md, "The chain", written out independently of the library's formula.
double same_material(double e, double nu, double reff) { return 2 * e / (3 * (1 - nu * nu)) * std::sqrt(reff); }

TEST(HertzContact, SphereSphereMatchesSpecTable) {
  const auto a11 = fixtures::reference("A11"), a12 = fixtures::reference("A12"), a22 = fixtures::reference("A22");
  EXPECT_NEAR(hertz_coefficient(steel, r1, steel, r1), a11.value, a11.tolerance);
  EXPECT_NEAR(hertz_coefficient(steel, r1, steel, r1 / 2), a12.value, a12.tolerance);
  EXPECT_NEAR(hertz_coefficient(steel, r1 / 2, steel, r1 / 2), a22.value, a22.tolerance);
}

TEST(HertzContact, SphereWallUsesTheSphereRadiusNotHalfOfIt) {
  // A classic DEM bug: treating the wall as a sphere of equal radius halves R_eff.
  const double by_hand = 2 * 193e9 / (3 * (1 - 0.09)) * std::sqrt(4.76e-3);
  const auto ref = fixtures::reference("A_wall_R1");
  EXPECT_NEAR(by_hand, ref.value, ref.tolerance);
  EXPECT_NEAR(hertz_coefficient(steel, flat_wall, steel, r1), ref.value, ref.tolerance);
  EXPECT_DOUBLE_EQ(hertz_coefficient(steel, r1, steel, flat_wall), hertz_coefficient(steel, flat_wall, steel, r1));
  EXPECT_NEAR(hertz_coefficient(steel, flat_wall, steel, r1) / hertz_coefficient(steel, r1, steel, r1), std::sqrt(2.0),
              1e-15);
}

TEST(HertzContact, MixedMaterialsFollowTheGeneralFormula) {
  const Material brass{103e9, 0.34, 8500};
  const Material ptfe{1.46e9, 0.46, 2200};
  const double ra = 3e-3, rb = 5e-3;
  const double reff = ra * rb / (ra + rb);
  // E* = 1 / ((1-ν_a²)/E_a + (1-ν_b²)/E_b), A = (4/3) E* sqrt(R_eff): the textbook form.
  auto textbook = [&](const Material& a, const Material& b, double r) {
    const double estar = 1 / ((1 - a.poisson * a.poisson) / a.young + (1 - b.poisson * b.poisson) / b.young);
    return 4.0 / 3.0 * estar * std::sqrt(r);
  };
  EXPECT_NEAR(hertz_coefficient(brass, ra, ptfe, rb), textbook(brass, ptfe, reff), 1e-12 * textbook(brass, ptfe, reff));
  EXPECT_NEAR(hertz_coefficient(ptfe, rb, brass, ra), textbook(brass, ptfe, reff), 1e-12 * textbook(brass, ptfe, reff));
  EXPECT_NEAR(hertz_coefficient(brass, flat_wall, steel, ra), textbook(brass, steel, ra),
              1e-12 * textbook(brass, steel, ra));
  EXPECT_NEAR(hertz_coefficient(steel, ra, steel, rb), same_material(193e9, 0.3, reff), 1e-3);

  // A chain of alternating steel and brass beads between PTFE walls: every bond by hand.
  ChainSpec spec;
  spec.radii = {ra, rb, ra};
  spec.materials = {steel, brass, steel};
  spec.left_wall = {ptfe, flat_wall};
  spec.right_wall = {brass, flat_wall};
  spec.walls_match_beads = false;
  spec.precompression = 2;
  const Chain c = make_chain(spec);
  ASSERT_EQ(c.bonds(), 4u);
  EXPECT_NEAR(c.contact[0], textbook(ptfe, steel, ra), 1e-12 * c.contact[0]);
  EXPECT_NEAR(c.contact[1], textbook(steel, brass, reff), 1e-12 * c.contact[1]);
  EXPECT_NEAR(c.contact[2], textbook(brass, steel, reff), 1e-12 * c.contact[2]);
  EXPECT_NEAR(c.contact[3], textbook(steel, brass, ra), 1e-12 * c.contact[3]);
  EXPECT_NEAR(c.mass[1], 8500 * 4.0 / 3.0 * M_PI * rb * rb * rb, 1e-18);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(c.contact[k] * std::pow(c.overlap[k], 1.5), 2.0, 1e-12);
}

TEST(HertzContact, RejectsTwoWallsAndBadRadii) {
  EXPECT_THROW(hertz_coefficient(steel, flat_wall, steel, flat_wall), InvalidInput);
  EXPECT_THROW(hertz_coefficient(steel, 0, steel, r1), InvalidInput);
  EXPECT_THROW(hertz_coefficient(steel, -1, steel, r1), InvalidInput);
}

}  // namespace
}  // namespace granular
