#pragma once
// Single-site kicks (SPEC §4): a displacement α or a velocity β at bead `site` (0-based),
// the rest of the chain at rest in its precompressed equilibrium.
#include <cstddef>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/state.hpp"

namespace granular {

/// u_n = α δ_{n,site}. Throws InvalidInput if the site is outside the chain, α is 0 or not
/// finite, or |α| plus the static overlap reaches a neighbouring bead's radius (the beads
/// would overlap past their centres, where Hertz means nothing).
State displacement_kick(const Chain& chain, std::size_t site, double alpha);

/// v_n = β δ_{n,site}. Throws InvalidInput on a bad site or β = 0 / not finite.
State velocity_kick(const Chain& chain, std::size_t site, double beta);

/// The β whose kinetic energy m β²/2 equals the energy of the displacement kick α on this
/// chain and force law ("match the energy of α"); 8.0359e-3 m/s for the homogeneous steel
/// chain at F0 = 10 N and α = 1e-7 m.
double matched_velocity(const ForceLaw& law, const Chain& chain, std::size_t site, double alpha);

/// Centre bead (0-based) of an N-bead chain: (N−1)/2, i.e. bead 1251 of 2501 counting from 1.
inline std::size_t centre_site(std::size_t n) { return (n - 1) / 2; }

}  // namespace granular
