// Invalid packings are refused with InvalidInput naming the option: too few beads, bad radii and
// masses, and packings that are not rigid under their load (docs/crystals.md, "Rigidity").
#include <gtest/gtest.h>

#include <string>

#include "granular/crystal/static_state.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

// The name InvalidInput carries, or its message when it names none; "" when nothing is thrown.
std::string refusal(const PackingSpec& spec) {
  try {
    static_state(make_packing(spec));
  } catch (const InvalidInput& e) {
    return e.parameter().empty() ? e.what() : e.parameter();
  }
  return "";
}

TEST(CrystalRefusals, TooFewBeadsBadRadiiAndMasses) {
  PackingSpec spec;
  PackingSpec bad = spec;
  bad.Lx = 1;
  EXPECT_EQ(refusal(bad), "Lx");
  bad = spec, bad.Ly = 1;
  EXPECT_EQ(refusal(bad), "Ly");
  bad = spec, bad.boundary = Boundary::periodic, bad.strain = 1e-3, bad.Lx = 2;
  EXPECT_EQ(refusal(bad), "Lx");  // a periodic row of two touches its neighbour twice
  bad = spec, bad.lattice = Lattice::hexagonal, bad.Ly = 5;
  EXPECT_EQ(refusal(bad), "Ly");
  bad = spec, bad.radius = -1e-3;
  EXPECT_EQ(refusal(bad), "radius");
  bad = spec, bad.radii.assign(64, 4e-3), bad.radii[7] = 0;
  EXPECT_EQ(refusal(bad), "radii");
  bad = spec, bad.radii.assign(63, 4e-3);
  EXPECT_EQ(refusal(bad), "radii");
  bad = spec, bad.materials.assign(64, steel), bad.materials[3].density = -1;  // a negative mass
  EXPECT_NE(refusal(bad).find("materials"), std::string::npos);
  bad = spec, bad.material.density = 0;
  EXPECT_NE(refusal(bad).find("material"), std::string::npos);
  bad = spec, bad.precompression = 0;
  EXPECT_EQ(refusal(bad), "precompression");
  bad = spec, bad.boundary = Boundary::periodic, bad.strain = 0;
  EXPECT_EQ(refusal(bad), "strain");
  try {
    disordered(spec, {.kind = PackingDisorder::Kind::mass, .width = 1.5, .seed = 1});
    ADD_FAILURE() << "width 1.5 accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "width");
  }
}

TEST(CrystalRefusals, CompressedPeriodicSquareIsNotRigid) {
  PackingSpec spec;
  spec.boundary = Boundary::periodic, spec.Lx = 4, spec.Ly = 4, spec.strain = 1e-3;
  EXPECT_EQ(refusal(spec), "packing");
  const StaticState s = static_state(make_packing(spec), {.require_rigid = false});
  EXPECT_FALSE(s.rigid);
  spec.lattice = Lattice::hexagonal;
  EXPECT_EQ(refusal(spec), "");  // the triangular lattice holds
}

TEST(CrystalRefusals, SquareWithWallsPastTheShearBound) {
  // Steel, R = 4.76 mm, F0 = 10 kN: δ = 128 µm, so k_n (1 − cos(π/(L+1))) > 2 f/d, i.e.
  // L + 1 < π sqrt(3d/(8δ)) = 16.5, holds for columns of 10 beads and fails for columns of 20.
  PackingSpec spec;
  spec.Lx = 4, spec.Ly = 10, spec.precompression = 1e4;
  EXPECT_EQ(refusal(spec), "");
  spec.Ly = 20;
  EXPECT_EQ(refusal(spec), "packing");
  spec.Lx = 20, spec.Ly = 4;  // the same with rows and columns exchanged
  EXPECT_EQ(refusal(spec), "packing");
}

TEST(CrystalRefusals, PolydisperseBeyondTheStaticOverlap) {
  // 1% of 4.76 mm is 48 µm, far wider than Δ = 5.9 µm at 100 N: beads lose their load.
  PackingSpec spec;
  spec.Lx = 8, spec.Ly = 8, spec.precompression = 100;
  EXPECT_EQ(refusal(disordered(spec, {.kind = PackingDisorder::Kind::radius, .width = 0.01, .seed = 5})), "packing");
}

}  // namespace
}  // namespace granular
