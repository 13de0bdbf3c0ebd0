#pragma once
// Time-periodic orbits of a chain by half-period shooting and Newton's method (docs/breathers.md).
//
// For a frequency ω_b, T = 2π/ω_b, the unknowns are the N displacements x0 of a state at rest,
// u(0) = x0, u̇(0) = 0, and the residual is r(x0) = u̇(T/2). Why this suffices and fixes the phase:
// the equations of motion are reversible (t → −t, u̇ → −u̇), and so is every symmetric splitting
// scheme of scheme.hpp (Φ_τ^{-1} = R Φ_τ R with R u̇ = −u̇). If the orbit from (x0, 0) is at rest
// again at T/2, in (x1, 0), reversibility sends it back to (x0, 0) at T: it is T-periodic, for the
// discrete map exactly (to rounding), not only to the order of the scheme. The time shifts of a
// periodic orbit, which make Φ_T(x) − x singular along the flow, are removed by asking for the
// orbit at a turning point (all velocities zero at t = 0), and N equations meet N unknowns.
//
// The Jacobian J = ∂u̇(T/2)/∂x0 is the lower-left block of the half-period tangent map: the
// deviation vectors (δu, δv) = (e_j, 0) carried along by the same scheme (tangent_map.hpp), one per
// bead, so the Jacobian is the exact derivative of the discrete map that is shot. For large N
// (Newton–Krylov) the matrix is never formed: GMRES needs only products J v, each one tangent
// integration of T/2 from (v, 0), preconditioned by the linearized chain's J (shooting_krylov.cpp).
//
//   auto law = granular::make_force_law(granular::ForceLawKind::hertz, chain);
//   auto orbit = granular::find_periodic_orbit(law, chain, omega_b, seed_x0);
//   for (double r : orbit.residuals) ...  // the Newton history
#include <cstddef>
#include <string>
#include <vector>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/dynamics/state.hpp"

namespace granular {

/// How Newton's correction is solved: dense — the N × N Jacobian (N tangent integrations) and
/// LAPACK; krylov — matrix-free GMRES on products J v (a few tangent integrations per step when
/// preconditioned); automatic — dense up to ShootingConfig::max_dense_beads, krylov beyond.
enum class NewtonMethod { automatic, dense, krylov };
NewtonMethod parse_newton_method(const std::string& name);  ///< "auto" | "dense" | "krylov"
std::string to_string(NewtonMethod method);

struct ShootingConfig {
  SplittingScheme scheme = saba2c();
  /// Steps of the scheme per period T (even: T/2 is a whole number of steps). 0: choose from the
  /// chain (shooting_steps).
  std::size_t steps_per_period = 0;
  double tolerance = 1e-10;  ///< converged when the relative residual ‖u̇(T/2)‖/(ω_b ‖x0‖) ≤ this
  int max_iterations = 25;   ///< Newton iterations before NumericalError
  /// The dense Jacobian costs N tangent integrations and an N × N solve per iteration; beyond this
  /// N automatic uses Newton–Krylov (also for the arclength corrector's bordered system), and dense
  /// is refused (InvalidInput naming N) rather than left to run for hours.
  std::size_t max_dense_beads = 1000;
  NewtonMethod newton = NewtonMethod::automatic;
  /// Krylov: GMRES iterations (no restart) per Newton step; a step whose GMRES residual stays above
  /// 1/2 of the right-hand side throws NumericalError.
  int max_krylov = 300;
  /// Krylov: right-precondition GMRES by the linearized chain's half-period Jacobian (needs F0 > 0;
  /// costs the N × N linear eigenvectors). Without it GMRES needs ~N iterations per step.
  bool precondition = true;
};

/// Whether find_periodic_orbit on N beads uses Newton–Krylov under `config` (throws InvalidInput
/// naming N when dense is asked for beyond max_dense_beads).
bool uses_newton_krylov(std::size_t beads, const ShootingConfig& config);

/// A default step count per period: the fastest linear mode ω_max (Gershgorin bound of the
/// linearized chain, on-site springs included) at ω_max τ ≤ 0.05, at least 128, even.
std::size_t shooting_steps(const Chain& chain, double omega);

/// u̇(T/2) from (x0, 0) and, if `jacobian`, J = ∂u̇(T/2)/∂x0 (N × N, column-major).
struct HalfPeriodMap {
  std::vector<double> velocity;  ///< u̇(T/2) [m/s]
  std::vector<double> jacobian;  ///< [1/s]; empty unless asked
};
HalfPeriodMap half_period_map(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                              std::size_t steps_per_period, double omega, const std::vector<double>& x0, bool jacobian);

/// The relative residual ‖u̇(T/2)‖₂ / (ω_b ‖x0‖₂): dimensionless, O(1) for a wrong amplitude
/// profile, 0 for a periodic orbit.
double relative_residual(const std::vector<double>& velocity, double omega, const std::vector<double>& x0);

struct PeriodicOrbit {
  double omega = 0;                  ///< ω_b [rad/s]
  double period = 0;                 ///< T = 2π/ω_b [s]
  std::size_t steps_per_period = 0;  ///< of the scheme
  double time_step = 0;              ///< τ = T/steps [s]
  SplittingScheme scheme;
  std::vector<double> x0;                ///< displacements at the turning point t = 0 [m]
  std::vector<double> residuals;         ///< relative residual before each Newton step and at the end
  int iterations = 0;                    ///< Newton steps taken
  std::string newton = "dense";          ///< "dense" or "krylov": how the corrections were solved
  std::vector<int> krylov_iterations;    ///< krylov: GMRES iterations of each Newton step
  std::vector<double> krylov_residuals;  ///< krylov: GMRES relative residual reached at each step
  double residual() const { return residuals.empty() ? 0.0 : residuals.back(); }
};

/// Newton's method from `guess` (N displacements [m]) at ω_b = `omega` [rad/s] (dense or
/// Newton–Krylov: ShootingConfig::newton; Krylov solves each step to a relative residual
/// min(1e-3, max(1e-12, 0.1 r)) at relative shooting residual r: superlinear), each step damped
/// (halved up to 10 times) until the residual decreases. Throws InvalidInput (N, omega, guess) or
/// NumericalError when it does not converge within max_iterations, or falls to the rest state
/// (‖x0‖ below 1e-6 of the guess's: the trivial orbit, which is every frequency's).
PeriodicOrbit find_periodic_orbit(const ForceLaw& law, const Chain& chain, double omega,
                                  const std::vector<double>& guess, const ShootingConfig& config = {});

/// A point predicted along a branch of orbits and the branch's direction there, for
/// pseudo-arclength correction. The direction is in scaled units: x by `x_scale` [m], ω_b by
/// `omega_scale` [rad/s] (e.g. the last point's ‖x0‖ and ω_b), so that both parts weigh alike.
struct ArcPrediction {
  std::vector<double> x;          ///< predicted displacements [m]
  double omega = 0;               ///< predicted ω_b [rad/s]
  std::vector<double> tangent_x;  ///< the branch's unit tangent: its x part (scaled)
  double tangent_omega = 0;       ///< … and its ω_b part (scaled)
  double x_scale = 1;             ///< [m]
  double omega_scale = 1;         ///< [rad/s]
};

/// Newton's method on (x0, ω_b) together: the N shooting equations and the pseudo-arclength
/// condition that the correction from the prediction be orthogonal to the tangent (in scaled
/// units). At a fold of the branch in ω_b, where find_periodic_orbit has no solution near its guess,
/// this bordered system stays regular, so a continuation can pass the fold. ∂u̇(T/2)/∂ω_b comes
/// from central differences of the map (relative step 1e-6) at the fixed config.steps_per_period,
/// which must be set (a step count that changed with ω_b would make the map jump). Converged when
/// the relative residual and the arclength condition are both ≤ config.tolerance; the same damping
/// and failures (NumericalError) as find_periodic_orbit; the residuals recorded are the shooting ones.
/// The bordered (N + 1) system is solved as config.newton says (uses_newton_krylov): densely by
/// LAPACK, or matrix-free by GMRES on the same system (its shooting rows' J v one tangent
/// integration each, right-preconditioned by the linearized chain's J as in find_periodic_orbit).
PeriodicOrbit find_periodic_orbit_on_arc(const ForceLaw& law, const Chain& chain, const ArcPrediction& prediction,
                                         const ShootingConfig& config);

/// The state (x0, 0) of an orbit at t = 0.
State turning_state(const PeriodicOrbit& orbit);

}  // namespace granular
