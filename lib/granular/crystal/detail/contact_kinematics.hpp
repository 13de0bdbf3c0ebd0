#pragma once
// The geometry and 2 × 2 stiffness block of one planar contact: the one home of these formulas,
// shared by the static Newton solve (its Hessian) and the crystal's dynamical matrix.
#include <array>
#include <cmath>

#include "granular/crystal/packing.hpp"

namespace granular::detail {

struct PlanarContact {
  double nx, ny;    ///< unit normal i → j
  double distance;  ///< centre distance d [m]
  double overlap;   ///< δ = R_i + R_j − d [m]
};

/// A bead contact whose beads moved by (dux, duy) relative to each other (u_j − u_i). The overlap is
/// the reference overlap minus the stretch d − a, computed as (d² − a²)/(d + a) from the displacement
/// alone, so that it keeps its digits although d is ~1e4 times larger than δ.
inline PlanarContact planar_contact(const BeadContact& c, double spacing, double dux, double duy) {
  const double rx = spacing * c.ex + dux, ry = spacing * c.ey + duy;
  const double d = std::hypot(rx, ry);
  const double stretch = (2 * spacing * (c.ex * dux + c.ey * duy) + dux * dux + duy * duy) / (d + spacing);
  return {rx / d, ry / d, d, c.reference_overlap - stretch};
}

/// Inward unit normal of a wall.
inline std::array<double, 2> wall_normal(WallSide wall) {
  switch (wall) {
    case WallSide::left: return {1, 0};
    case WallSide::right: return {-1, 0};
    case WallSide::bottom: return {0, 1};
    case WallSide::top: break;
  }
  return {0, -1};
}

/// Symmetric 2 × 2 block K = k_n n nᵀ − (f/d)(I − n nᵀ) [N/m] (xx, xy, yy); without the prestress
/// term when `prestress` is false.
struct Block2 {
  double xx, xy, yy;
};
inline Block2 contact_block(double kn, double f, double d, double nx, double ny, bool prestress) {
  const double t = prestress ? f / d : 0.0;
  return {kn * nx * nx - t * (1 - nx * nx), (kn + t) * nx * ny, kn * ny * ny - t * (1 - ny * ny)};
}

}  // namespace granular::detail
