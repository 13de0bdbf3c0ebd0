#pragma once
// Named constructors for the chains people build (docs/physics.md, "The chain" and "Disorder"): the paper's bidisperse
// steel beads (type 1 of radius R1, type 2 of radius ξ R1) between flat walls of the same steel.
//
//   auto chain = granular::anderson({.N = 100, .q = 0.5, .xi = 0.5, .seed = 1});
//   auto ref   = granular::diatomic({.N = 2000, .xi = 0.5, .F0 = 10});
//
// Fields a constructor does not use are ignored (a homogeneous chain has no q). Realization r of
// seed s is a pure function of (s, r, disorder, q, N): the same chain on any machine, thread or rank.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"

namespace granular {

/// The radius of the paper's type-1 beads [m].
inline constexpr double paper_r1 = 4.76e-3;

struct ChainParameters {
  std::size_t N = 100;            ///< beads, ≥ 2
  double q = 0.5;                 ///< probability of a type-1 bead (A), dimer "11" (RDM1) or "12" (RDM2), in [0, 1]
  double xi = 0.5;                ///< size ratio R2/R1 in (0, 1]
  std::uint64_t seed = 1;         ///< random seed
  std::uint64_t realization = 0;  ///< which realization of the seed
  double F0 = 10;                 ///< static precompression [N], ≥ 0 (0: the sonic vacuum)
  double R1 = paper_r1;           ///< type-1 radius [m]
  Material material = steel;      ///< beads and walls
};

/// Throws InvalidInput naming the field (N, q, xi, F0, R1, material) unless it is in range.
void validate(const ChainParameters& p);

/// Realization `p.realization` of seed `p.seed` of a disorder kind.
Chain random_chain(Disorder disorder, const ChainParameters& p);
inline Chain anderson(const ChainParameters& p) { return random_chain(Disorder::anderson, p); }
inline Chain rdm1(const ChainParameters& p) { return random_chain(Disorder::rdm1, p); }
inline Chain rdm2(const ChainParameters& p) { return random_chain(Disorder::rdm2, p); }
/// N type-1 beads.
inline Chain homogeneous(const ChainParameters& p) { return random_chain(Disorder::homogeneous, p); }
/// Alternating types 1, 2, 1, 2, … (the band edges fb1…fb3 are this chain's).
Chain diatomic(const ChainParameters& p);
/// A given sequence of types (1 or 2); p.N is ignored.
Chain from_types(const Configuration& types, const ChainParameters& p = {});
/// Beads of given radii [m] of one material; flat walls of the same material.
Chain from_radii(const std::vector<double>& radii, double F0 = 10, const Material& material = steel);

}  // namespace granular
