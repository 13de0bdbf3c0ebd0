#pragma once
// The disordered Klein–Gordon (DKG) chain (docs/physics.md, "The disordered Klein–Gordon chain"), the
// lattice whose weak and strong chaos the granular chains are compared with (Flach, Krimer & Skokos,
// PRL 102, 024101 (2009); Skokos, Krimer, Komineas & Flach, PRE 79, 056211 (2009)):
//
//   H = Σ_l p_l²/2 + ε̃_l x_l²/2 + x_l⁴/4 + (x_{l+1} − x_l)²/(2W),   ε̃_l uniform in [1/2, 3/2],
//
// in its customary dimensionless units: unit masses and quartic coefficient, time in units of
// 1/ω₀ (ω₀ = 1: an on-site oscillator of ε̃ = 1 at small amplitude), energy in those of H. Fixed ends x_0 = x_{N+1} = 0,
// so the end sites have a bond of stiffness 1/W to the wall like every other. As a Chain: masses 1, bonds the linear
// springs 1/W (Chain::spring), on-site springs k_l = ε̃_l with quartic part q_l = 1; no contacts (contact, overlap, F0
// are 0 and radii infinite: no bead size limits a displacement). It runs with the linear force law; the chain's SI
// annotations then read as these units.
//
//   auto chain = granular::klein_gordon({.N = 1000, .W = 4, .seed = 1});
//   auto law   = granular::make_force_law(granular::ForceLawKind::linear, chain);
#include <cstddef>
#include <cstdint>
#include <vector>

#include "granular/model/chain.hpp"

namespace granular {

struct KleinGordonParameters {
  std::size_t N = 1000;           ///< sites, 2 … 10⁸
  double W = 4;                   ///< disorder strength W > 0, finite: bonds of stiffness 1/W
  std::uint64_t seed = 1;         ///< random seed
  std::uint64_t realization = 0;  ///< which realization of the seed
};

/// Throws InvalidInput naming the field (N, W) unless it is in range.
void validate(const KleinGordonParameters& p);

/// ε̃_l of sites l = 1 … N: 1/2 plus the l-th uniform of the Philox stream keyed by (seed,
/// realization) (random_stream.hpp), so in [1/2, 3/2) and a pure function of (seed, realization).
std::vector<double> klein_gordon_disorder(const KleinGordonParameters& p);

/// Realization p.realization of seed p.seed of the DKG chain of p.N sites, as described above.
Chain klein_gordon(const KleinGordonParameters& p);

/// Bounds of the linear problem's squared frequencies: ω² ∈ [1/2, 3/2 + 4/W] for any realization.
struct KleinGordonBand {
  double omega2_min, omega2_max;
};
KleinGordonBand klein_gordon_band(double W);

}  // namespace granular
