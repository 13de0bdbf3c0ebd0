#pragma once
// Dissipation (SPEC §4 "Beyond the paper"): on-site viscous damping −(m_n/τ_d) u̇_n and
// Kuwabara–Kono contact damping, bond force γ_KK A_k [δ_k]_+^{1/2} δ̇_k (δ̇_k = u̇_{k−1} − u̇_k),
// acting only while bond k is in contact (δ_k = Δ_k + x_k > 0).
//
// Integration: Strang splitting of the conservative scheme Φ_τ with the damping flow D_h at
// fixed positions, one step = D_{τ/2} Φ_τ D_{τ/2}. For fixed u the damping is linear in v:
//   M v̇ = −(M/τ_d) v − C(u) v,   C(u) = the tridiagonal, positive semi-definite bond Laplacian
//                                        with weights c_k = γ_KK A_k [δ_k]_+^{1/2};
// the on-site part is a multiple of the identity, so it commutes with the rest and its flow is
// exact (v ← v e^{−h/τ_d}); the contact part takes one trapezoidal (Crank–Nicolson) step,
// (M + hC/2) v' = (M − hC/2) v: A-stable, 2nd order, one O(N) tridiagonal solve, and it never
// adds kinetic energy. The composite is therefore 2nd order in τ whatever the conservative
// scheme (measured: tests/dynamics/damping_test.cpp). The kinetic energy each damping substep
// removes is summed exactly, so H(t) + dissipated(t) = H(0) up to the conservative scheme's
// own energy error.
//
// The contact weights use the chain's Hertz geometry (A_k, Δ_k) for every force law: the
// damping is a property of the contact, whichever expansion of its elastic force is integrated.
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "granular/dynamics/propagator.hpp"

namespace granular {

struct Damping {
  double time = 0;      ///< τ_d [s] of the on-site damping −(m/τ_d) u̇; 0: none
  double kk_gamma = 0;  ///< γ_KK [s] of the Kuwabara–Kono contact damping; 0: none
  bool any() const { return time > 0 || kk_gamma > 0; }
};

/// Throws InvalidInput (parameter `damping_time` or `kk_gamma`) unless both are finite and ≥ 0.
void validate(const Damping& damping);

/// The damping flow over h at fixed positions, with its workspace allocated once.
class DampingFlow {
 public:
  DampingFlow(const Chain& chain, const Damping& damping);
  /// v ← D_h v given the displacements u (N beads, walls at 0). Returns the kinetic energy
  /// removed [J] (≥ 0 up to rounding).
  double apply(std::span<const double> u, std::span<double> v, double h);

 private:
  Damping damping_;
  std::vector<double> mass_, contact_, overlap_;
  std::vector<double> weight_, diag_, upper_, rhs_;  // workspace
};

/// The damped splitting propagator D_{τ/2} Φ_τ D_{τ/2} on the whole chain (no active window:
/// dissipation is for chains of experimental size). Its dissipated_energy() is the running sum.
std::unique_ptr<Propagator> make_damped_propagator(const ForceLaw& law, const Chain& chain,
                                                   const SplittingScheme& scheme, double time_step,
                                                   const State& initial, const Damping& damping);

}  // namespace granular
