#pragma once
// The coefficient of restitution of one head-on collision of two equal beads with Kuwabara–Kono
// contact damping (docs/beyond-the-paper.md), integrated with the same damped splitting
// scheme as the chain (damping.hpp): bead 1 hits bead 2, at rest, with the impact speed; the
// beads touch at t = 0 without overlap; no walls, no precompression. e is the ratio of the
// separation speed to the impact speed once the contact has opened. Use it to calibrate γ_KK
// against a measured e. At small damping 1 − e ≈ C1 γ_KK (A/μ)^{2/5} v^{1/5}, μ the reduced mass,
// C1 = 1.15344 (Schwager & Pöschel, PRE 57, 650 (1998)). Check: to first order in γ_KK the energy
// lost is ∫ γ_KK A δ^{1/2} δ̇² dt along the elastic orbit, which gives 1 − e = 2 (5/4)^{3/5}
// (2/5) B(3/5, 3/2) γ_KK (A/μ)^{2/5} v^{1/5} = 1.1534 γ_KK (A/μ)^{2/5} v^{1/5}.
#include <string>

#include "granular/model/material.hpp"
#include "granular/model/named_chains.hpp"

namespace granular {

struct CollisionConfig {
  Material material = steel;
  double radius = paper_r1;           ///< R of both beads [m] (the paper's type-1 beads)
  double impact_speed = 0.01;         ///< v > 0 [m/s]
  double kk_gamma = 0;                ///< γ_KK ≥ 0 [s]
  double steps_per_collision = 4000;  ///< τ = (Hertz contact time at v) / this
  std::string integrator = "saba2c";  ///< the splitting scheme
};

struct Collision {
  double restitution = 0;     ///< e = separation speed / impact speed
  double contact_time = 0;    ///< from touch to separation [s] (to one step τ)
  double max_overlap = 0;     ///< largest compression [m] (at step boundaries)
  double hertz_time = 0;      ///< the elastic contact time 3.218 (μ/A)^{2/5} v^{−1/5} = 2.943 δ_max/v [s]
  double time_step = 0;       ///< τ used [s]
  double dissipated = 0;      ///< energy removed [J]
  double initial_energy = 0;  ///< m v²/2 [J]
};

/// Throws InvalidInput (`impact_speed`, `kk_gamma`, `radius`, `steps_per_collision`) on bad input,
/// NumericalError if the contact has not opened after 20 Hertz contact times.
Collision two_bead_collision(const CollisionConfig& config);

/// The elastic (Hertz) contact time 2 (δ_max/v) ∫₀¹ dx/√(1 − x^{5/2}) ≈ 3.218 (μ/A)^{2/5} v^{−1/5} [s].
double hertz_contact_time(const CollisionConfig& config);

/// The small-damping prediction of 1 − e (Schwager & Pöschel 1998) for these beads.
double restitution_deficit_small_damping(const CollisionConfig& config);

}  // namespace granular
