#pragma once
// The beads of a linearized chain, read a piece at a time (docs/physics.md, "Infinite chains"): what
// the transfer-matrix methods need, which walk the chain once from wall to wall and never need
// all of it at once. A random realization is drawn lazily from its counter-based stream, so a
// 10⁸-bead chain costs memory O(piece), not O(N), and gives exactly the beads that
// `realization_configuration` + `make_chain` give.
//
// Indexing as in chain.hpp: beads 0 … N-1; bond k (0 … N) joins bead k-1 and bead k, bond 0 and
// bond N are the walls.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"
#include "granular/model/named_chains.hpp"

namespace granular {

class BeadSource {
 public:
  virtual ~BeadSource() = default;
  /// N, the number of beads.
  virtual std::size_t size() const = 0;
  /// Masses m_n [kg] of beads first … first+count-1 into `mass` (count values) and linear
  /// stiffnesses B_k [N/m] of bonds first … first+count, the bonds on either side of them, into
  /// `stiffness` (count+1 values). Requires first + count ≤ N. Const and thread-safe: any thread
  /// may read any piece, in any order.
  virtual void read(std::size_t first, std::size_t count, double* mass, double* stiffness) const = 0;
  /// Whether beads are held to the ground by linear springs (Chain::onsite, the quasiperiodic
  /// chain S1); read_onsite then gives them. False for every other chain.
  virtual bool grounded() const { return false; }
  /// On-site stiffnesses k_n [N/m] of beads first … first+count-1 into `onsite` (count values),
  /// zeros when not grounded(). Same contract as read.
  virtual void read_onsite(std::size_t /*first*/, std::size_t count, double* onsite) const {
    for (std::size_t i = 0; i < count; ++i) onsite[i] = 0;
  }
};

/// Realization p.realization of seed p.seed of a disordered chain of p.N beads — the chain
/// random_chain(disorder, p) builds — drawn on demand: bead i (dimer j) from the i-th (j-th)
/// uniform of the Philox stream keyed by (seed, realization), exactly as
/// realization_configuration does. Memory O(1), so p.N is not limited to the 1e8 beads of a
/// stored Chain. Throws InvalidInput naming the field (N, q, xi, F0, R1, material); F0 must be
/// > 0 (the sonic vacuum has no linear limit).
std::unique_ptr<BeadSource> random_beads(Disorder disorder, const ChainParameters& p);

/// A given sequence of bead types (1 or 2), e.g. from a configuration file: the chain
/// from_types(types, p) builds (p.N, p.q, p.seed, p.realization ignored). Memory N bytes.
std::unique_ptr<BeadSource> typed_beads(Configuration types, const ChainParameters& p = {});

/// Any chain (radii file, several materials, other walls, on-site springs): masses, B_k =
/// linear_stiffness of its contact coefficients and the on-site k_n, copied (memory 2N or 3N
/// doubles). Throws InvalidInput if F0 = 0, unless the bonds are linear springs (Chain::spring).
std::unique_ptr<BeadSource> chain_beads(const Chain& chain);

}  // namespace granular
