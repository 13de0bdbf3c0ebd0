#pragma once
// Dissipation (docs/beyond-the-paper.md): on-site viscous damping −(m_n/τ_d) u̇_n and
// Kuwabara–Kono contact damping, bond force γ_KK A_k [δ_k]_+^{1/2} δ̇_k (δ̇_k = u̇_{k−1} − u̇_k),
// acting only while bond k is in contact (δ_k = Δ_k + x_k > 0).
//
// Integration: splitting of the conservative scheme Φ_τ with the damping flow at fixed
// positions. For fixed u the damping is linear in v:
//   M v̇ = −(M/τ_d) v − C(u) v,   C(u) = Σ_k C_k, C_k the bond-k Laplacian with weight
//                                        c_k = γ_KK A_k [δ_k]_+^{1/2} (positive semi-definite);
// the on-site part is a multiple of the identity, so it commutes with the rest and its flow is
// exact (v ← v e^{−h/τ_d}). The contact part is split by the parity of the bonds, E (even bonds
// 0, 2, 4, …) and O (odd bonds), because the bonds of one parity share no bead: each is an
// independent two-bead problem whose relative velocity g = v_{k−1} − v_k obeys ġ = −λ_k g,
// λ_k = c_k (1/m_{k−1} + 1/m_k) (a wall has 1/m = 0), while the pair's momentum stays as it is.
// Each pair takes its exact flow at fixed positions, g ← g e^{−hλ_k}: L-stable (a stiff contact's g
// decays to 0 instead of flipping sign every step, as Crank–Nicolson's (1 − hλ/2)/(1 + hλ/2) does
// for hλ/2 > 1), momentum-conserving, and it never adds kinetic energy. One damped step is
// the symmetric composition
//   E_{τ/2} O_{τ/2} Φ_τ O_{τ/2} E_{τ/2}   (in time order; the on-site flow over τ/2 at both ends),
// the Strang splitting of three flows, so 2nd order whatever the conservative scheme (measured:
// tests/dynamics/damping_test.cpp); the same pieces as E_{h/2} O_h E_{h/2} approximate the
// damping flow alone to 2nd order (against the exact flow of the whole C:
// tests/dynamics/damping_flow_test.cpp). With one contact (a two-bead collision) the step is
// Φ_τ between two exact half-step flows of that contact's damping. Unlike a tridiagonal solve over
// the chain there is no sequential recurrence: every pass vectorizes (docs/beyond-the-paper.md,
// Speed). The kinetic energy each damping substep removes is summed exactly, so
// H(t) + dissipated(t) = H(0) up to the conservative scheme's own energy error.
//
// The contact weights use the chain's Hertz geometry (A_k, Δ_k) for every force law: the
// damping is a property of the contact, whichever expansion of its elastic force is integrated.
#include <cstddef>
#include <initializer_list>
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
  /// v ← D_h v given the displacements u (N beads, walls at 0), D_h = E_{h/2} O_h E_{h/2} with the
  /// on-site flow: a 2nd-order approximation of the damping flow on its own. Returns the kinetic
  /// energy removed [J] (≥ 0 up to rounding).
  double apply(std::span<const double> u, std::span<double> v, double h);
  /// One sweep, every pair taking its exact flow over h: even bonds first (E_h O_h) or odd
  /// first (O_h E_h), with the on-site flow over h. Each is 1st order; the damped step is
  /// E_{τ/2} O_{τ/2} Φ_τ O_{τ/2} E_{τ/2}, the symmetric composition, 2nd order.
  enum class Sweep { even_first, odd_first };
  double apply(std::span<const double> u, std::span<double> v, double h, Sweep order);

  const Damping& damping() const { return damping_; }
  /// Per bond k: (h/2) γ_KK A_k (1/m_{k−1} + 1/m_k), so that the pair step of h is
  /// g ← g e^{−2 y_k}, y_k = rate_k [δ_k]_+^{1/2} (= h λ_k / 2). Set by apply(), or by prepare(h).
  const double* rate() const { return rate_.data(); }
  /// The same per unit Hertz stiffness K_k = (3/2) A_k [δ_k]_+^{1/2}: y_k = rate_per_stiffness_k K_k.
  const double* rate_per_stiffness() const { return rate_per_stiffness_.data(); }
  /// Per padded position p (bead p−1; 0 and N+1 the walls), for the bonds of one parity: the
  /// share of the pair's relative-velocity change g that bead takes, with its sign, so that every
  /// member updates as v ← v − share·g: m_k/(m_{k−1}+m_k) for bead k−1, the left one of bond k,
  /// and −m_{k−1}/(m_{k−1}+m_k) for bead k, the right one; a wall takes none.
  /// Both members' shares sit side by side, which keeps the pair loop's loads contiguous.
  const double* pair_share(std::size_t parity) const { return parity == 0 ? share_even_.data() : share_odd_.data(); }
  const double* overlap() const { return overlap_.data(); }
  /// Fixes h for rate().
  void prepare(double h);

 private:
  double sweep(std::span<const double> u, std::span<double> v, double h, std::initializer_list<std::size_t> parities,
               std::initializer_list<double> fractions);

  Damping damping_;
  double h_ = 0;
  std::vector<double> mass_, contact_, overlap_, sum_im_, share_even_, share_odd_, rate_, rate_per_stiffness_;
  std::vector<double> vp_, loss_;  // workspace of apply()
};

/// The damped splitting propagator E_{τ/2} O_{τ/2} Φ_τ O_{τ/2} E_{τ/2} on the whole chain (no
/// active window: dissipation is for chains of experimental size). Its dissipated_energy() is
/// the running sum. Within one advance() the damping substeps that meet at a step boundary
/// (same positions; E_{τ/2} E_{τ/2} as two exact pair steps) run as one blocked pass with the
/// SABA2C correctors on either side and the next drift; the kicks are the conservative stepper's
/// blocked kernels. With no damping at all (Damping::any() false) it is the
/// conservative stepper on the whole chain. Throws InvalidInput naming kk_gamma for contact
/// damping on a chain without contacts (linear spring bonds, Chain::spring).
std::unique_ptr<Propagator> make_damped_propagator(const ForceLaw& law, const Chain& chain,
                                                   const SplittingScheme& scheme, double time_step,
                                                   const State& initial, const Damping& damping);

}  // namespace granular
