#pragma once
// The maximal Lyapunov exponent by the tangent map method (docs/beyond-the-paper.md;
// Skokos & Gerlach, PRE 82, 036704 (2010)). A deviation vector w = (δu, δv) obeys the
// variational equations δu̇ = δv, m_n δv̇_n = −Σ_j (∂²V/∂u_n∂u_j) δu_j, whose matrix is the
// tridiagonal bond-stiffness Laplacian (K_k = f_k'(x_k)). Integrating them with the same
// splitting scheme as the orbit is the tangent map: every drift moves δu by δv, every kick
// moves δv by the stiffness Laplacian of δu at the kick's positions, and the SABA2C corrector
// kick by its own derivative (which needs f_k'', the bond curvature). The result is the exact
// derivative of the discrete orbit map, so the deviation vector equals the difference of two
// nearby numerical orbits divided by their distance, to first order.
//
// Norm: ‖w‖² = Σ_n δu_n² + (t_unit δv_n)², t_unit = 1 µs (a fixed scale making u and v
// commensurate; the exponent's limit does not depend on it). Every `renormalize_every` steps
// w is scaled back to norm 1 and ln‖w‖ added to the running sum S; X1(t) = S(t)/t.
// Regular (e.g. linear) motion gives X1 ∝ ln t / t, chaos a positive limit.
#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "granular/dynamics/propagator.hpp"

namespace granular {

struct LyapunovConfig {
  bool enabled = false;
  std::size_t renormalize_every = 10;  ///< steps between renormalizations; 0: never (raw w)
  double time_unit = 1e-6;             ///< t_unit of the norm [s]
};

/// A conservative propagator that carries a deviation vector along (whole chain, no active
/// window: the deviation vector does not stay where the energy is).
class TangentPropagator : public Propagator {
 public:
  virtual std::span<const double> deviation_displacement() const = 0;  ///< δu (current, scaled)
  virtual std::span<const double> deviation_velocity() const = 0;      ///< δv
  /// How many deviation vectors the map carries along the one orbit (1 unless made with several).
  virtual std::size_t deviation_count() const = 0;
  /// δu and δv of vector j < deviation_count() (j = 0: the vector above).
  virtual std::span<const double> deviation_displacement(std::size_t j) const = 0;
  virtual std::span<const double> deviation_velocity(std::size_t j) const = 0;
  /// Vector j < deviation_count() as a State (a copy: δu in u, δv in v).
  State deviation(std::size_t j) const;
  /// Every vector, deviation(0) … deviation(deviation_count() − 1).
  std::vector<State> deviations() const;
  /// Replaces vector j (N values each): what a re-orthonormalization writes back.
  virtual void set_deviation(std::size_t j, std::span<const double> du, std::span<const double> dv) = 0;
  /// ln(‖w(t)‖/‖w(0)‖) including every renormalization so far.
  virtual double log_stretch() const = 0;
  /// X1(t) = log_stretch / t [1/s]; 0 at t = 0.
  double mle() const { return time() > 0 ? log_stretch() / time() : 0.0; }
  /// Share of ‖w‖² on each bead, (δu_n² + (t_unit δv_n)²)/‖w‖²: where the chaos sits.
  std::vector<double> deviation_distribution() const;
  virtual double time_unit() const = 0;
};

/// Starts the orbit at `initial` and the deviation vector at `deviation` (both N beads;
/// the deviation must be finite and non-zero).
std::unique_ptr<TangentPropagator> make_tangent_propagator(const ForceLaw& law, const Chain& chain,
                                                           const SplittingScheme& scheme, double time_step,
                                                           const State& initial, const State& deviation,
                                                           const LyapunovConfig& config = {.enabled = true});

/// The same map carrying k = deviations.size() vectors (1 ≤ k ≤ 2N) along one orbit, for Lyapunov
/// spectra (lyapunov_spectrum.hpp): the orbit and vector 0 exactly as above (so the orbit is the
/// plain run's bit for bit), each further vector by the same expressions from the bond stiffnesses,
/// curvatures and accelerations the orbit's pass leaves (no further force evaluations). Several
/// vectors are not renormalized one by one: every config.renormalize_every steps (0: never) the
/// map calls `orthonormalize` on itself between two steps, without breaking the merged drifts of
/// a stretch of steps (so the orbit stays the plain run's, whatever the interval), and the owner
/// re-orthonormalizes the vectors together (set_deviation).
std::unique_ptr<TangentPropagator> make_tangent_propagator(const ForceLaw& law, const Chain& chain,
                                                           const SplittingScheme& scheme, double time_step,
                                                           const State& initial, const std::vector<State>& deviations,
                                                           const LyapunovConfig& config,
                                                           std::function<void(TangentPropagator&)> orthonormalize = {});

/// The orbit from `initial` after `steps` steps of τ and the images of the deviation vectors
/// `deviations` under the tangent map of those steps (raw: no renormalization), for Jacobians and
/// monodromy matrices (periodic_orbit.hpp, floquet.hpp). Each vector is carried by its own tangent
/// propagator, so the orbit is recomputed per vector (cost: deviations × one orbit); every copy of
/// the orbit is the same bit for bit.
struct TangentImages {
  State orbit;                    ///< the state after the steps
  std::vector<State> deviations;  ///< the deviation vectors after the steps
};
TangentImages propagate_deviations(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                                   double time_step, std::size_t steps, const State& initial,
                                   const std::vector<State>& deviations);

/// The default starting deviation: δu = 1 and δv = 1/t_unit on bead `site` (where the energy is
/// put in), zero elsewhere.
State localized_deviation(std::size_t beads, std::size_t site, double time_unit = 1e-6);

}  // namespace granular
