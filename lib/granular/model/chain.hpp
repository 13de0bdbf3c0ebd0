#pragma once
// A chain of N beads between two fixed walls, with its static precompression (docs/physics.md, "The chain").
//
// Indexing is 0-based: particles 0 … N-1; bond k (0 … N) joins particle k-1 and particle k,
// where "particle -1" is the left wall and "particle N" the right wall. Per-bond arrays have
// N+1 entries, per-particle arrays N.
#include <cstddef>
#include <vector>

#include "granular/model/contact_law.hpp"
#include "granular/model/material.hpp"

namespace granular {

/// A fixed end of the chain. A flat wall by default; a finite radius models a fixed sphere
/// (a wall whose bond equals a bulk bond, handy for exact checks).
struct Wall {
  Material material = steel;
  double radius = flat_wall;
};

/// What a chain is made of; `make_chain` validates it.
struct ChainSpec {
  std::vector<double> radii;        ///< bead radii [m], N ≥ 2 entries
  std::vector<Material> materials;  ///< one material for all beads, or one per bead
  Wall left_wall;
  Wall right_wall;
  double precompression = 10.0;   ///< static force F0 ≥ 0 [N]; 0 is the sonic vacuum
  bool walls_match_beads = true;  ///< walls take the material of their neighbouring bead
};

struct Chain {
  std::vector<double> radius;        ///< R_n [m]
  std::vector<double> mass;          ///< m_n = ρ (4/3) π R_n³ [kg]
  std::vector<double> inverse_mass;  ///< 1/m_n [1/kg]
  std::vector<double> contact;       ///< A_k [N/m^{3/2}], N+1 bonds
  std::vector<double> overlap;       ///< static overlap Δ_k = (F0/A_k)^{2/3} [m], N+1 bonds
  double precompression = 0;         ///< F0 [N]
  /// k_n [N/m] of a linear spring holding bead n to the ground (the quasiperiodic chain S1,
  /// docs/physics.md, "Quasiperiodic chains"); empty when the beads have none (every other chain).
  std::vector<double> onsite;
  /// q_n [N/m³] of a quartic part of those springs: force −k_n u − q_n u³, energy ½ k_n u² + ¼ q_n u⁴
  /// (the disordered Klein–Gordon chain, klein_gordon/klein_gordon.hpp); empty when they are linear.
  std::vector<double> onsite_quartic;
  /// Linear bond springs B_k [N/m] given directly, N+1 bonds, in place of Hertz contacts (the
  /// Klein–Gordon chain's 1/W; there contact, overlap and F0 are 0); empty for every granular chain,
  /// whose B_k come from A_k and F0.
  std::vector<double> spring;

  std::size_t size() const { return radius.size(); }
  std::size_t bonds() const { return contact.size(); }
};

/// Builds masses, contact coefficients and static overlaps; throws InvalidInput on bad specs.
Chain make_chain(const ChainSpec& spec);

/// B_k = (3/2) A_k^{2/3} F0^{1/3} of every bond (N+1 values) [N/m]: the linearized chain; the
/// springs themselves when the chain has linear springs for bonds (Chain::spring).
std::vector<double> linear_stiffness(const Chain& chain);

/// Convenience: beads of one material with the given radii, flat walls of the same material.
Chain make_chain(const std::vector<double>& radii, double precompression, const Material& material = steel);

}  // namespace granular
