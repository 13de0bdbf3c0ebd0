#pragma once
// Mode-shaped kicks: the nonlinear dynamics started from one linear mode of the same chain (the
// paper's outlook: "the spreading can be considerably slower" from a mode than from one site).
// Here the linear module (which mode, its shape) meets the dynamics (a state, an energy): the
// eigenvector w of the mass-weighted dynamical matrix D gives the displacements u = M^{-1/2} w,
// released from rest, so under the linear force law the chain stays in that mode for ever.
//
//   auto k   = granular::mode_kick(chain, granular::ForceLawKind::hertz, {.near_khz = 30, .energy = 1e-7});
//   auto r   = granular::run_spreading(chain, k.initial, config);  // spreading_run.hpp
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/state.hpp"
#include "granular/linear/dynamical_matrix.hpp"

namespace granular {

/// Which mode, and how large. Exactly one of `mode` and `near_khz` chooses; `energy`, when > 0,
/// sets the size, otherwise `amplitude` does.
struct ModeKick {
  long mode = 0;                     ///< mode number 1…N by increasing frequency; 0: use near_khz
  std::optional<double> near_khz{};  ///< the mode nearest this frequency [kHz] (ties: the lower); none: use mode
  double energy = 0;                 ///< total energy H [J] under the run's force law; 0: use amplitude
  double amplitude = 0;              ///< largest |u_n| [m] when energy is 0
};

/// Throws InvalidInput (naming `mode`, `near_khz`, `energy` or `amplitude`) unless exactly one
/// selector and one size are given and make sense for an N-bead chain.
void validate(const ModeKick& kick, std::size_t beads);

struct ModeKickResult {
  State initial;               ///< u = a · v / max|v| with v = M^{-1/2} w, v = 0
  std::size_t mode = 0;        ///< its number 1…N
  double freq_khz = 0;         ///< its linear frequency [kHz]
  double omega2 = 0;           ///< ω² [1/s²]
  double ipr = 0;              ///< its displacement IPR Σv⁴/(Σv²)²
  double amplitude = 0;        ///< largest |u_n| [m]
  double energy = 0;           ///< H of the initial state under the force law [J]
  std::size_t peak_site = 0;   ///< 0-based bead of the largest |u_n| (the mode's centre)
  std::vector<double> vector;  ///< the unit eigenvector w of D (N entries, largest entry positive)
};

/// The mode of `chain` chosen by `kick`, as an initial state for `law`. Throws InvalidInput (bad
/// kick, F0 = 0: no linear modes), NumericalError (the eigensolver failed).
ModeKickResult mode_kick(const Chain& chain, ForceLawKind law, const ModeKick& kick);

/// mode, freq_khz, ipr, amplitude_m, energy_J, peak_site (counting from 1): what a run's metadata says.
nlohmann::json to_json(const ModeKickResult& kick);

/// The fraction of the harmonic energy of `state` that mode (w, ω²) of `d` carries:
/// ½(ṗ² + ω² p²) / (½ vᵀMv + ½ uᵀKu) with p = wᵀM^{1/2}u, ṗ = wᵀM^{1/2}v. 1 exactly for a state in
/// that mode; its complement is what the nonlinearity has moved into the other modes.
double mode_energy_fraction(const DynamicalMatrix& d, std::span<const double> w, double omega2, const State& state);

/// P⁻¹ of the phase-free amplitudes A_n = sqrt(u_n² + v_n²/ω²): Σ A⁴ / (Σ A²)². For a chain
/// oscillating in one mode of frequency ω every A_n is constant in time and this is the mode's
/// displacement IPR; the energy P⁻¹ of run_spreading is not constant even then (each bead's energy
/// swings between its kinetic and its potential share twice a period).
double mode_amplitude_ipr(const State& state, double omega2);

}  // namespace granular
