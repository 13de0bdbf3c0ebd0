#pragma once
// What is measured on a state (docs/physics.md, "Nonlinear dynamics"): site energies, total energy, the energy-based second
// moment m̃2 and participation P⁻¹, and the forces on the beads. Beads outside [begin, end)
// are taken to be exactly at rest (the active window), which makes their energy exactly 0.
#include <cstddef>
#include <span>
#include <string>
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

/// About which bead the second moment is taken (docs/physics.md, "Observables").
enum class SpreadCentre {
  /// The excited bead n0: the paper's definition. It writes its kicks as δ_{n,n_c} and calls n_c
  /// "the position of the center of the distribution", so n_c is the kicked site.
  site,
  /// The energy centroid n̄ = Σ n E_n / Σ E_n: the width of the packet about where it is, the
  /// better measure when the energy leaves mostly to one side (velocity kicks near F0 = 0).
  centroid,
};
SpreadCentre parse_spread_centre(const std::string& name);  ///< "site" | "centroid"
std::string to_string(SpreadCentre centre);

struct EnergySpread {
  double total = 0;        ///< Σ E_n [J]
  double centroid = 0;     ///< n̄ = Σ n E_n / Σ E_n (0-based bead index)
  double m2_site = 0;      ///< m̃2 about the excited bead n0: Σ (n − n0)² E_n / Σ E_n [bead²]
  double m2_centroid = 0;  ///< m̃2 about n̄; m2_site = m2_centroid + (n̄ − n0)² exactly
  double ipr = 0;          ///< P⁻¹ = Σ E_n² / (Σ E_n)², in (0, 1]
  double m2(SpreadCentre c) const { return c == SpreadCentre::site ? m2_site : m2_centroid; }
};
/// Spread of the energy profile `energy` about the excited bead `site` (0-based) and about its
/// centroid. All zero when Σ E_n is not positive. Only beads [begin, end) are read: those outside
/// must hold no energy (an active window's resting beads), and then the result is the whole
/// profile's to the last bit (adding +0 changes no sum).
EnergySpread energy_spread(std::span<const double> energy, std::size_t site, std::size_t begin = 0,
                           std::size_t end = static_cast<std::size_t>(-1));

/// Force on each bead: the mean of its two compressive contact forces (static + dynamic),
/// (f_n + f_{n+1})/2, what a sensor embedded in the bead reads. At rest it is F0.
void particle_forces(const ForceLaw& law, std::span<const double> u, std::span<double> force);
std::vector<double> particle_forces(const ForceLaw& law, const State& state);

}  // namespace granular
