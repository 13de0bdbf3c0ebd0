#pragma once
// The Newton correction of half-period shooting without the Jacobian matrix (periodic_orbit.cpp):
// GMRES on J δ = −u̇(T/2), J v one tangent integration of half a period from (v, 0), right-
// preconditioned by the linearized chain's half-period Jacobian (see shooting_krylov.cpp).
#include <cstddef>
#include <vector>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/scheme.hpp"

namespace granular::detail {

struct KrylovCorrection {
  std::vector<double> step;  ///< δ [m] (bordered: N + 1 scaled unknowns)
  int iterations = 0;        ///< GMRES iterations (tangent integrations of T/2)
  double residual = 0;       ///< ‖J δ + u̇‖ / ‖u̇‖ reached
};

/// The bordered system of pseudo-arclength correction (periodic_orbit.cpp), in scaled unknowns
/// (δ, η) (N + 1): [s J  b; t_xᵀ  t_ω] (δ, η) = rhs, with J the half-period shooting Jacobian.
struct BorderedSystem {
  double jacobian_scale = 1;      ///< s: the shooting rows' scale times x's unit
  std::vector<double> column;     ///< b: the shooting rows' derivative along ω_b (scaled), N
  std::vector<double> tangent_x;  ///< the arclength row's x part, N
  double tangent_omega = 0;       ///< … and its ω_b part
  std::vector<double> rhs;        ///< N + 1
};

class ShootingKrylov {
 public:
  /// Builds the preconditioner (the chain's linear modes: an N × N eigenvector matrix) unless
  /// `precondition` is false.
  ShootingKrylov(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme, std::size_t steps_per_period,
                 double omega, bool precondition);
  /// GMRES (no restart) to the relative residual `tolerance` or `max_iterations`, at x0 = `x`
  /// where u̇(T/2) = `velocity`.
  KrylovCorrection solve(const std::vector<double>& x, const std::vector<double>& velocity, double tolerance,
                         int max_iterations) const;
  /// GMRES (no restart) on a bordered system at x0 = `x`, right-preconditioned by
  /// diag(J_lin⁻¹ / s, 1): the border adds rank 2 to what the preconditioner leaves, and at a fold
  /// (J singular along the branch) the bordered matrix stays regular. Returns the N + 1 unknowns.
  KrylovCorrection solve_bordered(const std::vector<double>& x, const BorderedSystem& system, double tolerance,
                                  int max_iterations) const;
  /// Moves the frequency (time step and preconditioner gains; the modes are kept): along an arc
  /// every Newton iterate has its own ω_b.
  void set_frequency(double omega);
  /// J v at x0 = `x`: one tangent integration of T/2.
  std::vector<double> jacobian_times(const std::vector<double>& x, const std::vector<double>& v) const;
  /// The preconditioner: J_lin⁻¹ y (identity when not preconditioning).
  std::vector<double> precondition(const std::vector<double>& y) const;

 private:
  const ForceLaw& law_;
  const Chain& chain_;
  SplittingScheme scheme_;
  std::size_t steps_;
  double tau_ = 0;
  std::vector<double> modes_;         // N × N unit eigenvectors of D, column-major
  std::vector<double> mode_omega_;    // their ω_k [rad/s]
  std::vector<double> inverse_gain_;  // 1 / (−ω_k sin(π ω_k/ω_b)) [s]
  std::vector<double> inverse_sqrt_mass_;
};

}  // namespace granular::detail
