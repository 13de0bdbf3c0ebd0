#pragma once
// Single-site kicks (docs/physics.md, "Nonlinear dynamics"): a displacement α or a velocity β at bead `site` (0-based),
// the rest of the chain at rest in its precompressed equilibrium.
#include <cstddef>
#include <cstdint>
#include <span>

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

/// u = a · shape / max|shape|, v = 0: a whole-chain displacement profile (e.g. a linear mode's
/// displacements, from case/mode_kick.hpp) whose largest |u_n| is `amplitude` a [m], the chain at
/// a turning point. Throws InvalidInput (naming `shape` or `amplitude`) on a shape of the wrong
/// length, all zero or not finite, on a ≤ 0 or not finite, or when a bond's static overlap plus
/// its strain reaches a bead radius.
State shaped_displacement(const Chain& chain, std::span<const double> shape, double amplitude);

/// The amplitude a [m] of shaped_displacement(chain, shape, a) whose energy H under `law` is
/// `energy` [J], to 1e-14 relative: H(a) grows with a for a > 0 (every bond potential here is
/// convex near zero strain with its minimum there), so a bisection finds it. Throws InvalidInput
/// naming `energy` when it is ≤ 0, not finite, or not reached before the beads would overlap.
double shaped_amplitude_for_energy(const ForceLaw& law, const Chain& chain, std::span<const double> shape,
                                   double energy);

/// u = 0, v_n = √(2E/m_n) at `site`: an energy E [J] all kinetic on one bead. The disordered
/// Klein–Gordon chain's single-site excitation (p_l = √(2E), unit masses). Throws InvalidInput on
/// a bad site or E ≤ 0 / not finite.
State site_energy_kick(const Chain& chain, std::size_t site, double energy);

/// u = 0, v_n = ±√(2h/m_n) on the `length` beads first … first + length − 1: each with energy
/// density h [J per bead] all kinetic, signs at random (the Klein–Gordon chain's block excitation,
/// p_l = ±√(2h)). Bead j's sign is from uniform j of the Philox stream of (seed, realization)
/// counted from 2⁶² (random_stream.hpp): a pure function of (seed, realization), independent of
/// the chain that stream's first uniforms draw. Throws InvalidInput naming `site`, `length` or
/// `energy_density`.
State block_energy_kick(const Chain& chain, std::size_t first, std::size_t length, double energy_density,
                        std::uint64_t seed, std::uint64_t realization = 0);

/// Centre bead (0-based) of an N-bead chain: (N−1)/2, i.e. bead 1251 of 2501 counting from 1.
inline std::size_t centre_site(std::size_t n) { return (n - 1) / 2; }

}  // namespace granular
