// The static Newton solve: force balance on every bead, the perfect lattices' analytic contact
// forces, and disordered packings that must be solved (docs/crystals.md, "The static state").
#include "granular/crystal/static_state.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "granular/error.hpp"
#include "granular/model/contact_law.hpp"

namespace granular {
namespace {

double worst_imbalance(const Packing& p, const StaticState& s) {
  const auto each = bead_imbalance(p, s);
  return *std::max_element(each.begin(), each.end());
}

TEST(StaticState, PerfectSquareWithWallsCarriesF0InEveryContact) {
  PackingSpec spec;
  spec.Lx = 6, spec.Ly = 5, spec.precompression = 10;
  const Packing p = make_packing(spec);
  const StaticState s = static_state(p);
  EXPECT_EQ(s.iterations, 0);
  EXPECT_TRUE(s.rigid);
  EXPECT_EQ(p.contacts.size(), 5u * 5 + 6u * 4);  // (Lx − 1) Ly + Lx (Ly − 1)
  EXPECT_EQ(p.wall_contacts.size(), 2u * 5 + 2u * 6);
  for (double f : s.force) EXPECT_NEAR(f, 10.0, 1e-13);
  for (double f : s.wall_force) EXPECT_NEAR(f, 10.0, 1e-13);
  EXPECT_LE(worst_imbalance(p, s), 1e-12);
}

TEST(StaticState, MassDisorderKeepsTheLatticesStaticState) {
  PackingSpec spec;
  spec.lattice = Lattice::hexagonal, spec.Lx = 6, spec.Ly = 6;
  const StaticState plain = static_state(make_packing(spec));
  const Packing p = make_packing(disordered(spec, {.kind = PackingDisorder::Kind::mass, .width = 0.5, .seed = 2}));
  const StaticState s = static_state(p);
  EXPECT_EQ(s.force, plain.force);
  EXPECT_EQ(s.ux, plain.ux);
  EXPECT_NE(p.mass[0], p.mass[1]);
}

TEST(StaticState, HexagonalPeriodicUnderStrainHasTheUniformForce) {
  PackingSpec spec;
  spec.lattice = Lattice::hexagonal, spec.boundary = Boundary::periodic, spec.Lx = 6, spec.Ly = 4, spec.strain = 1e-3;
  const Packing p = make_packing(spec);
  const StaticState s = static_state(p);
  EXPECT_TRUE(s.rigid);
  EXPECT_EQ(p.contacts.size(), 3u * 24);
  const double A = hertz_coefficient(steel, spec.radius, steel, spec.radius);
  const double expected = A * std::pow(2 * spec.radius * spec.strain, 1.5);  // F = A δ^{3/2}, δ = 2Rε
  for (double f : s.force) EXPECT_NEAR(f, expected, 1e-13 * expected);
  EXPECT_LE(worst_imbalance(p, s), 1e-12);
}

TEST(StaticState, HexagonalWithWallsAndMaterialDisorderBalanceAt1e12) {
  PackingSpec spec;
  spec.lattice = Lattice::hexagonal, spec.Lx = 8, spec.Ly = 8, spec.precompression = 10;
  for (const PackingSpec& each :
       {spec, disordered(spec, {.kind = PackingDisorder::Kind::material, .width = 0.2, .seed = 3})}) {
    const Packing p = make_packing(each);
    const StaticState s = static_state(p);
    EXPECT_GT(s.iterations, 0);
    EXPECT_TRUE(s.rigid);
    EXPECT_LE(worst_imbalance(p, s), 1e-12);
    EXPECT_LE(s.imbalance, 1e-12);
    // The walls carry their loads: F0 per bead they touch.
    for (WallSide w : {WallSide::left, WallSide::right, WallSide::bottom, WallSide::top}) {
      double total = 0;
      for (std::size_t k = 0; k < p.wall_contacts.size(); ++k)
        if (p.wall_contacts[k].wall == w) total += s.wall_force[k];
      EXPECT_NEAR(total, p.wall_load[static_cast<std::size_t>(w)], 1e-11 * total);
    }
  }
}

TEST(StaticState, PolydisperseSquareWithWallsConvergesAndBalances) {
  // Radius spread w R must stay below the static overlap, or rows stop touching the walls: here
  // F0 = 10 kN gives Δ = 128 µm and w = 1% spreads radii by ±48 µm (at 100 N, Δ = 5.9 µm, it is
  // refused: refusals_test). 12 beads per row stay below the shear bound.
  PackingSpec spec;
  spec.Lx = 12, spec.Ly = 12, spec.precompression = 1e4;
  const Packing p = make_packing(disordered(spec, {.kind = PackingDisorder::Kind::radius, .width = 0.01, .seed = 5}));
  const StaticState s = static_state(p);
  EXPECT_GT(s.iterations, 0);
  EXPECT_TRUE(s.rigid);
  EXPECT_LE(worst_imbalance(p, s), 1e-12);
  EXPECT_TRUE(s.open_contacts.empty());
  const auto [lo, hi] = std::minmax_element(s.force.begin(), s.force.end());
  EXPECT_LT(*lo, 0.99 * *hi);  // the forces are no longer uniform
}

TEST(StaticState, ReportsOrRefusesContactsThatOpen) {
  // Radius spread 1e-3 R = 4.8 µm on a hexagonal torus with δ = 2Rε = 2.9 µm: some contacts open,
  // and six contacts per bead keep the packing rigid.
  PackingSpec spec;
  spec.lattice = Lattice::hexagonal, spec.boundary = Boundary::periodic, spec.Lx = 8, spec.Ly = 8, spec.strain = 3e-4;
  const Packing p = make_packing(disordered(spec, {.kind = PackingDisorder::Kind::radius, .width = 1e-3, .seed = 2}));
  const StaticState s = static_state(p);
  EXPECT_TRUE(s.rigid);
  EXPECT_LE(worst_imbalance(p, s), 1e-12);
  ASSERT_FALSE(s.open_contacts.empty());
  std::size_t open = 0;
  for (std::size_t k = 0; k < s.overlap.size(); ++k) {
    open += s.overlap[k] <= 0;
    if (s.overlap[k] <= 0) {
      EXPECT_EQ(s.force[k], 0.0);
    }
  }
  EXPECT_EQ(s.open_contacts.size(), open);
  try {
    static_state(p, {.refuse_open_contacts = true});
    ADD_FAILURE() << "open contacts accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "packing");
  }
}

}  // namespace
}  // namespace granular
