#pragma once
// The dynamical matrix of a packing about its static state (docs/crystals.md, "The dynamical
// matrix"): D = M^{-1/2} K M^{-1/2} [1/s²], 2N × 2N, degrees of freedom (x, y) of bead b at rows
// 2b and 2b+1, every wall held where the static state left it.
//
// A bead contact pushing with force f at centre distance d along the unit normal n adds the block
//     K_c = k_n n nᵀ − (f/d)(I − n nᵀ),   k_n = dF/dδ = (3/2) A δ^{1/2}   [N/m]
// to both beads' diagonal blocks and −K_c to the two off-diagonal ones (the Hessian of the energy
// (2/5) A δ^{5/2}, δ = R_i + R_j − d). The second term is the prestress: sliding bead j by s across
// the normal leaves d unchanged to first order but turns the contact force by the angle s/d, so f
// pushes j further along s. The transverse stiffness is thus −f/d: negative, because f pushes.
// A wall contact adds k_n n nᵀ to its bead's diagonal block and nothing else: the normal of a flat
// wall does not turn when the bead slides along it (the plane has no curvature, d → ∞ in f/d).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "granular/crystal/packing.hpp"
#include "granular/crystal/static_state.hpp"
#include "granular/linear/sparse_symmetric.hpp"

namespace granular {

struct CrystalMatrixConfig {
  /// Keep the prestress term −(f/d)(I − n nᵀ). Without it the rows and columns of a square
  /// packing with walls decouple into independent 1D chains (a test against the 1D toolkit).
  bool prestress = true;
};

/// D as a sparse symmetric matrix (linear/sparse_symmetric.hpp: compressed rows, both triangles,
/// symmetric to the bit) with the masses that weight it.
struct CrystalMatrix {
  SparseSymmetric matrix;                        ///< D [1/s²], 2N × 2N
  std::vector<double> inverse_sqrt_mass;         ///< m_b^{-1/2} [kg^{-1/2}], N entries
  std::size_t rows() const { return matrix.n; }  ///< 2N
  std::size_t beads() const { return inverse_sqrt_mass.size(); }
};

/// D about `state` (from static_state of the same packing). Throws InvalidInput naming `state` when
/// the state does not belong to the packing.
CrystalMatrix crystal_matrix(const Packing& packing, const StaticState& state, const CrystalMatrixConfig& config = {});

/// D as a dense row-major 2N × 2N array (small crystals: 8 (2N)² bytes).
std::vector<double> dense(const CrystalMatrix& d);

}  // namespace granular
