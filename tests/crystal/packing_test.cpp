// The packings' geometry: neighbour counts, the reference vectors of every contact (images
// included), the walls' contacts and loads, and reproducible disorder (docs/crystals.md, "Packings").
#include "granular/crystal/packing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace granular {
namespace {

void expect_reference_vectors(const Packing& p) {
  for (const BeadContact& c : p.contacts) {
    const double rx = p.x[c.j] + c.image_x * p.box_x - p.x[c.i], ry = p.y[c.j] + c.image_y * p.box_y - p.y[c.i];
    EXPECT_NEAR(rx, p.spacing * c.ex, 1e-15) << c.i << " -> " << c.j;
    EXPECT_NEAR(ry, p.spacing * c.ey, 1e-15) << c.i << " -> " << c.j;
    EXPECT_NEAR(std::hypot(c.ex, c.ey), 1.0, 1e-15);
  }
}

TEST(Packing, PeriodicLatticesHaveFourAndSixNeighboursPerBead) {
  for (Lattice lattice : {Lattice::square, Lattice::hexagonal}) {
    PackingSpec spec;
    spec.lattice = lattice, spec.boundary = Boundary::periodic, spec.Lx = 6, spec.Ly = 4, spec.strain = 1e-3;
    const Packing p = make_packing(spec);
    std::vector<int> neighbours(p.size(), 0);
    for (const BeadContact& c : p.contacts) ++neighbours[c.i], ++neighbours[c.j];
    for (int n : neighbours) EXPECT_EQ(n, lattice == Lattice::square ? 4 : 6);
    EXPECT_TRUE(p.wall_contacts.empty());
    expect_reference_vectors(p);
    EXPECT_NEAR(p.uniform_overlap, 2 * spec.radius * spec.strain, 1e-20);
  }
}

TEST(Packing, HexagonalSideWallsTouchEveryOtherRow) {
  PackingSpec spec;
  spec.lattice = Lattice::hexagonal, spec.Lx = 5, spec.Ly = 6, spec.precompression = 10;
  const Packing p = make_packing(spec);
  expect_reference_vectors(p);
  std::vector<int> per_wall(4, 0);
  for (const WallContact& w : p.wall_contacts) ++per_wall[static_cast<std::size_t>(w.wall)];
  EXPECT_EQ(per_wall, (std::vector<int>{3, 3, 5, 5}));
  EXPECT_EQ(p.wall_load[0], 30.0);  // F0 per bead touched
  EXPECT_EQ(p.wall_load[3], 50.0);
  EXPECT_EQ(p.contacts.size(), 6u * 4 + 5u * 9);  // rows: Lx − 1 each; between rows: 2 Lx − 1
}

TEST(Packing, DisorderIsReproducibleAndKeepsWhatItShould) {
  PackingSpec spec;
  spec.Lx = 4, spec.Ly = 3;
  const PackingSpec a = disordered(spec, {.kind = PackingDisorder::Kind::mass, .width = 0.2, .seed = 3});
  const PackingSpec b = disordered(spec, {.kind = PackingDisorder::Kind::mass, .width = 0.2, .seed = 3});
  ASSERT_EQ(a.materials.size(), 12u);
  for (std::size_t k = 0; k < 12; ++k) {
    EXPECT_EQ(a.materials[k].density, b.materials[k].density);
    EXPECT_EQ(a.materials[k].young, spec.material.young);
    EXPECT_LE(std::fabs(a.materials[k].density / spec.material.density - 1), 0.2);
  }
  const Packing p = make_packing(a);
  for (const BeadContact& c : p.contacts) EXPECT_EQ(c.contact, p.contacts[0].contact);  // same A everywhere
  const PackingSpec r = disordered(spec, {.kind = PackingDisorder::Kind::radius, .width = 0.01, .seed = 3});
  ASSERT_EQ(r.radii.size(), 12u);
  EXPECT_NE(r.radii[0], r.radii[1]);
}

}  // namespace
}  // namespace granular
