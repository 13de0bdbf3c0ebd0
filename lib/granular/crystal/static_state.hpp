#pragma once
// The static state of a packing (docs/crystals.md, "The static state"): bead positions at which
// every bead's Hertz normal contact forces F = A δ^{3/2} balance, found by Newton's method on the
// contact network, with the energy Hessian as the Jacobian (a supernodal sparse Cholesky, CHOLMOD) and a backtracking
// line search (a step must lower the energy or the force residual); a step reuses the last factors
// while steps keep cutting the imbalance fourfold (a chord step), started from the packing's
// uniformly compressed lattice. Where the Hessian is not positive definite (open contacts at the
// start leave beads that carry nothing) the step is a Levenberg one, H + μI.
//
// Loads. With walls, each wall pushes along its inward normal with F0 per bead it touches
// (Packing::wall_load). The left and bottom walls are held where they are and the right and top
// walls move until their contacts carry that load: force-controlled walls alone would leave the
// whole packing free to slide, a zero mode of the Hessian. By global balance the fixed walls then
// carry the same load. For the spectrum every wall is held where it ended. Periodic packings are
// held by their compressed torus; bead 0 is pinned against the two translations.
//
// Rigidity. The Hessian of the energy (with the walls' two free positions) must be positive
// definite at the solution, or the packing is not rigid under its load and is refused. The
// transverse stiffness of a contact pushing with force f at centre distance d is −f/d
// (crystal_matrix.hpp), so a compressed square packing, whose rows and columns have no normal
// stiffness transverse to themselves, holds only through its walls: with u_y = φ(j)(−1)^i across
// the rows, the columns' springs give k_n·2(1 − cos(π/(Ly+1))) and the rows' prestress takes away
// (f/d)·2(1 + cos(π/Lx)), so a square packing with walls is rigid only while roughly
//     k_n (1 − cos(π/(Ly+1))) > 2 f/d,   i.e.  Ly + 1 < π sqrt(3d/(8δ))   (k_n = (3/2) f/δ),
// and the same with Lx and Ly exchanged (the walls' own stiffness differs from k_n, hence
// "roughly"). Steel beads of 4.76 mm: about Ly < 165 at F0 = 10 N, Ly < 15 at 10 kN. A periodic
// compressed square lattice is never rigid (Bloch modes with q ∥ the rows and polarization across
// them have ω² = −(2/m)(f/d)(1 − cos qa) < 0); the hexagonal lattice is, for small strains.
#include <array>
#include <cstddef>
#include <vector>

#include "granular/crystal/packing.hpp"

namespace granular {

struct StaticConfig {
  /// Stop when every bead's imbalance (StaticState::imbalance) is ≤ this [-], or at the rounding
  /// floor, when no step lowers the residual and the imbalance is ≤ 1e3 × this.
  double tolerance = 1e-13;
  int max_iterations = 60;  ///< Newton steps
  /// Refuse (InvalidInput naming `packing`) a packing whose Hessian is not positive definite at the
  /// solution; false returns it with rigid = false (to study the unstable periodic square lattice).
  bool require_rigid = true;
  /// Refuse (InvalidInput naming `packing`) a state in which contacts opened, rather than report
  /// them (StaticState::open_contacts): for studies that need the lattice's contact network intact.
  bool refuse_open_contacts = false;
};

struct StaticState {
  std::vector<double> ux, uy;          ///< displacement of each bead from its reference centre [m]
  std::array<double, 4> wall_shift{};  ///< inward displacement of each wall (WallSide order) [m]
  // Per Packing::contacts entry:
  std::vector<double> overlap;    ///< δ [m] (≤ 0: the contact opened)
  std::vector<double> force;      ///< f = A [δ]_+^{3/2} [N], pushing the beads apart
  std::vector<double> stiffness;  ///< k_n = dF/dδ = (3/2) A [δ]_+^{1/2} [N/m]
  std::vector<double> distance;   ///< centre distance d [m]
  std::vector<double> nx, ny;     ///< unit normal from bead i to bead j
  // Per Packing::wall_contacts entry:
  std::vector<double> wall_overlap, wall_force, wall_stiffness;  ///< δ [m], f [N], k_n [N/m]
  std::vector<std::size_t> open_contacts;                        ///< indices of contacts with δ ≤ 0
  std::vector<std::size_t> open_wall_contacts;                   ///< indices of wall contacts with δ ≤ 0
  int iterations = 0;                                            ///< Newton steps taken, chord steps included
  double imbalance = 0;  ///< max over beads of |Σ forces| / Σ |forces| (and over free walls, / load)
  bool rigid = false;    ///< the Hessian is positive definite at the solution
};

/// The equilibrium of `packing` under its loads. Throws InvalidInput naming `packing` when it is not
/// rigid under them (Newton without a converging step, or an indefinite Hessian with require_rigid),
/// and InvalidInput naming the field of a bad config.
StaticState static_state(const Packing& packing, const StaticConfig& config = {});

/// |Σ forces on b| / Σ |forces on b| [-] for every bead (0 for a bead without closed contacts).
std::vector<double> bead_imbalance(const Packing& packing, const StaticState& state);

}  // namespace granular
