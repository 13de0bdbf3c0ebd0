#pragma once
// A planar packing of Lx × Ly spheres (docs/crystals.md, "Packings"): a square or a hexagonal
// (triangular-lattice) arrangement, its beads, its Hertz contacts and its boundary.
//
// Beads are numbered row by row, b = j·Lx + i (column i, row j; rows are horizontal). Positions
// are kept as a reference lattice, uniformly compressed, plus displacements (static_state.hpp):
// an overlap is then the reference overlap minus a small change, never the difference of two
// centre distances ~1e4 times larger, which would lose 4 of the 16 digits.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "granular/model/material.hpp"

namespace granular {

enum class Lattice {
  square,     ///< beads at a·(i, j)
  hexagonal,  ///< triangular lattice, horizontal rows, odd rows shifted by a/2: a·(i + (j mod 2)/2, j·√3/2)
};
enum class Boundary {
  walls,     ///< four flat rigid walls; each pushes with F0 per bead it touches (static_state.hpp)
  periodic,  ///< a torus under an imposed uniform compressive strain (for tests against Bloch waves)
};
std::string_view to_string(Lattice lattice);
std::string_view to_string(Boundary boundary);

/// What a packing is made of; make_packing validates it.
struct PackingSpec {
  Lattice lattice = Lattice::square;
  Boundary boundary = Boundary::walls;
  long Lx = 8;                      ///< beads per row, ≥ 2 (periodic: ≥ 3)
  long Ly = 8;                      ///< rows, ≥ 2 (periodic: ≥ 3; hexagonal: even, so the torus closes and the
                                    ///< side walls touch as many rows each)
  double radius = 4.76e-3;          ///< nominal radius R [m]: the lattice's; beads without `radii` have it
  Material material = steel;        ///< every bead's, unless `materials`
  std::vector<double> radii;        ///< per bead [m] (Lx·Ly entries), or empty: all `radius`
  std::vector<Material> materials;  ///< per bead (Lx·Ly entries), or empty: all `material`
  std::optional<Material> wall_material;  ///< walls; empty: each wall contact takes its bead's material
  double precompression = 10.0;           ///< walls: F0 > 0 [N] pushed by each wall per bead it touches
  double strain = 0;                      ///< periodic: ε in [0, 0.1): neighbour distance 2R(1 − ε)
};

/// Disorder drawn into a spec, reproducibly: bead b takes the b-th uniform of the random stream
/// (seed, realization), whatever thread or order draws it (model/random_stream.hpp).
struct PackingDisorder {
  enum class Kind {
    mass,      ///< density ρ(1 + w u): same size and elastic constants, so the static state is the lattice's
    material,  ///< Young modulus E(1 + w u): the contacts' A differ, the static state moves
    radius,    ///< radius R(1 + w u), polydisperse: keep w·R well below the static overlap or contacts open
  } kind = Kind::mass;
  double width = 0.1;  ///< w in [0, 1): u is uniform on [−1, 1]
  std::uint64_t seed = 1;
  std::uint64_t realization = 0;
};
/// `spec` with per-bead densities, materials or radii drawn; throws InvalidInput naming `width`.
PackingSpec disordered(PackingSpec spec, const PackingDisorder& disorder);

/// A Hertz contact between beads i and j. With periodic boundaries j may be an image: the torus
/// closes the lattice, and j's centre seen from i is (x_j + image_x box_x, y_j + image_y box_y).
struct BeadContact {
  std::size_t i = 0, j = 0;
  double ex = 0, ey = 0;         ///< unit vector i → j of the reference lattice (spacing · e apart)
  double contact = 0;            ///< Hertz A [N/m^{3/2}] (model/contact_law.hpp)
  double reference_overlap = 0;  ///< R_i + R_j − reference distance [m]
  int image_x = 0, image_y = 0;  ///< periodic image of j: −1, 0 or 1 torus periods
};

/// The four walls, each with its inward normal: left (+x), right (−x), bottom (+y), top (−y).
enum class WallSide { left = 0, right = 1, bottom = 2, top = 3 };

/// A Hertz sphere–plane contact (the 1D chain's flat wall: hertz_coefficient with flat_wall).
struct WallContact {
  std::size_t bead = 0;
  WallSide wall = WallSide::left;
  double contact = 0;            ///< A [N/m^{3/2}]
  double reference_overlap = 0;  ///< R_b − distance of the reference centre from the reference wall [m]
};

struct Packing {
  Lattice lattice = Lattice::square;
  Boundary boundary = Boundary::walls;
  long Lx = 0, Ly = 0;
  double nominal_radius = 0;          ///< R [m]
  double spacing = 0;                 ///< reference neighbour distance a [m] (2R minus the uniform overlap)
  double uniform_overlap = 0;         ///< 2R − a [m]: walls (F0/A)^{2/3} of two nominal beads; periodic 2Rε
  double precompression = 0;          ///< walls: F0 [N]; periodic: 0
  std::array<double, 4> wall_load{};  ///< walls: total force of each wall, F0 × beads it touches [N]
  std::vector<double> x, y;           ///< reference centres [m] (periodic: in a box box_x × box_y)
  double box_x = 0, box_y = 0;        ///< periodic: torus periods [m]
  std::vector<double> radius;         ///< R_b [m]
  std::vector<double> mass;           ///< m_b [kg]
  std::vector<Material> material;
  std::vector<BeadContact> contacts;
  std::vector<WallContact> wall_contacts;

  std::size_t size() const { return radius.size(); }
};

/// The packing: reference positions, masses, contacts; throws InvalidInput naming the field (Lx, Ly,
/// radius, radii, materials, precompression, strain) when a spec is invalid.
Packing make_packing(const PackingSpec& spec);

}  // namespace granular
