#pragma once
// What is measured on a state (SPEC §4): site energies, total energy, the energy-based second
// moment m̃2 and participation P⁻¹, and the forces on the beads. Beads outside [begin, end)
// are taken to be exactly at rest (the active window), which makes their energy exactly 0.
#include <cstddef>
#include <span>
#include <vector>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/state.hpp"

namespace granular {

/// x_k = u_{k−1} − u_k with the walls at 0 (bond k joins bead k−1 and bead k).
inline double bond_strain(std::span<const double> u, std::size_t k) {
  return (k > 0 ? u[k - 1] : 0.0) - (k < u.size() ? u[k] : 0.0);
}

/// E_n = m_n v_n²/2 + (φ_n + φ_{n+1})/2 for every bead; beads outside [begin, end) get 0.
void site_energies(const ForceLaw& law, const Chain& chain, std::span<const double> u, std::span<const double> v,
                   std::span<double> energy, std::size_t begin = 0, std::size_t end = static_cast<std::size_t>(-1));
std::vector<double> site_energies(const ForceLaw& law, const Chain& chain, const State& state);

/// H = Σ E_n plus the halves of the two wall bonds that belong to no bead: the conserved energy.
double total_energy(const ForceLaw& law, const Chain& chain, const State& state);
/// (φ_0 + φ_N)/2: the halves of the wall bonds that no bead owns. Without them H is not
/// conserved once energy reaches a wall.
double unowned_wall_energy(const ForceLaw& law, std::span<const double> u);

struct EnergySpread {
  double total = 0;   ///< Σ E_n
  double centre = 0;  ///< n_c = Σ n E_n / Σ E_n (0-based bead index)
  double m2 = 0;      ///< m̃2 = Σ (n − n_c)² E_n / Σ E_n
  double ipr = 0;     ///< P⁻¹ = Σ E_n² / (Σ E_n)²
};
EnergySpread energy_spread(std::span<const double> energy);

/// Force on each bead: the mean of its two compressive contact forces (static + dynamic),
/// (f_n + f_{n+1})/2, what a sensor embedded in the bead reads. At rest it is F0.
void particle_forces(const ForceLaw& law, std::span<const double> u, std::span<double> force);
std::vector<double> particle_forces(const ForceLaw& law, const State& state);

}  // namespace granular
