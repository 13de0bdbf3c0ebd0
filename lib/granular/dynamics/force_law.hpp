#pragma once
// Bond force laws of the chain (docs/physics.md, "The chain", §3, §4): Hertz, its FPU cubic expansion, linear.
//
// Every law answers, for bond k and strain x = u_{k-1} − u_k (positive = more compression):
//   force(k, x)        the force beyond the static one, f_k(x) − f_k(0); the equation of motion
//                      is m_i a_i = f_i(x_i) − f_{i+1}(x_{i+1})
//   stiffness(k, x)    f_k'(x), used by the SABA2C corrector
//   potential(k, x)    φ_k(x) with φ_k(0) = 0 and φ_k' = force (the static force F0 x term
//                      cancels between bonds, docs/physics.md, "Nonlinear dynamics")
//   contact_force(k,x) the full compressive contact force (static + dynamic), ≥ 0 for Hertz
// and, for the beads, the on-site springs of the chain (OnsiteSprings: none for most chains).
// The rest force f_k(0) is subtracted per bond with the very expression the kernel uses, so
// the undisturbed chain is an exact equilibrium in floating point: quiescent particles stay
// exactly at rest, which the active window relies on.
//
// Hot loops use `view()`: a trivially copyable struct of restrict pointers whose inline
// functions the compiler vectorizes; the law object owns the arrays.
#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "granular/model/chain.hpp"

namespace granular {

enum class ForceLawKind {
  hertz,   ///< A [Δ + x]_+^{3/2}: beads may separate; F0 = 0 allowed
  fpu,     ///< B1 x + B2 x² + B3 x³, the cubic expansion of Hertz about F0 > 0
  linear,  ///< B1 x, the linearization about F0 > 0
};
ForceLawKind parse_force_law(std::string_view name);
std::string to_string(ForceLawKind kind);

/// The springs holding bead n to the ground (Chain::onsite, the quasiperiodic chain S1; with
/// Chain::onsite_quartic, the Klein–Gordon chain): force −k_n u_n − q_n u_n³ [N] on bead n, energy
/// ½ k_n u_n² + ¼ q_n u_n⁴ [J]. Every law carries them, so that each integrator adds them where it
/// adds the bond forces, once; kernels read them from the view's `onsite` (k_n) and
/// `onsite_quartic` (q_n) pointers, null when the chain has none (then they run the loops without
/// them unchanged) through the inline onsite_* functions below, their one home.
class OnsiteSprings {
 public:
  explicit OnsiteSprings(const Chain& chain);
  bool grounded() const { return !k_.empty(); }
  /// Whether the springs have a quartic part (then grounded() too).
  bool quartic() const { return !q_.empty(); }
  /// k_n [N/m] per bead, or null.
  const double* onsite_data() const { return k_.empty() ? nullptr : k_.data(); }
  /// q_n [N/m³] per bead, or null.
  const double* onsite_quartic_data() const { return q_.empty() ? nullptr : q_.data(); }
  /// ½ k_n u² + ¼ q_n u⁴ [J] of bead n at displacement u [m]; 0 without springs.
  double onsite_potential(std::size_t n, double u) const {
    if (k_.empty()) return 0.0;
    return q_.empty() ? 0.5 * k_[n] * u * u : u * u * (0.5 * k_[n] + 0.25 * q_[n] * u * u);
  }
  /// k_n [N/m], the stiffness at rest; 0 without springs.
  double onsite_stiffness(std::size_t n) const { return k_.empty() ? 0.0 : k_[n]; }
  /// The largest stiffness k_n + 3 q_n u² [N/m] of bead n's spring at any u whose spring energy is
  /// ≤ `energy` [J]: at ½ k u² + ¼ q u⁴ = E, q u² = √(k² + 4 q E) − k. k_n for linear springs.
  double onsite_stiffness_bound(std::size_t n, double energy) const {
    if (q_.empty() || !(q_[n] > 0)) return onsite_stiffness(n);
    return 3 * std::sqrt(k_[n] * k_[n] + 4 * q_[n] * energy) - 2 * k_[n];
  }

 private:
  std::vector<double> k_, q_;
};

/// The formulas below are written once for a value type T: double for one bond, or a native
/// vector of doubles for one bond of several chains side by side (lanes/detail/lane_kernels.hpp,
/// which supplies ValueMath for its vector), so both give the same bits in every lane.
template <class T>
struct ValueMath;
template <>
struct ValueMath<double> {
  static double root(double x) { return std::sqrt(x); }
  static double positive_part(double x) { return std::max(x, 0.0); }  // branch-free (maxsd)
  static double at_least(double x, double low) { return std::max(x, low); }
};

/// The restoring force k u + q u³ [N] of an on-site spring (the force is its negative) and its
/// stiffness k + 3 q u² [N/m], with (`quartic`) or without the quartic part.
template <bool quartic, class T>
inline T onsite_restoring_of(T k, T q, T u) {
  if constexpr (quartic) return (k + q * u * u) * u;
  else return k * u;
}
template <bool quartic, class T>
inline T onsite_hessian_of(T k, T q, T u) {
  if constexpr (quartic) return k + 3 * q * u * u;
  else return k;
}
/// The quartic on-site spring's curvature 6 q u [N/m²] (the tangent map's corrector needs it).
template <class T>
inline T onsite_curvature_of(T q, T u) {
  return 6 * q * u;
}

/// Hertz's force beyond the static one, A [Δ + x]_+^{3/2} − rest, and (with it) its stiffness
/// 1.5 A [Δ + x]_+^{1/2}, of a bond of contact factor A, overlap Δ and rest force `rest`.
template <class T>
inline T hertz_force_of(T contact, T overlap, T rest, T x) {
  const T d = ValueMath<T>::positive_part(overlap + x);
  return contact * d * ValueMath<T>::root(d) - rest;
}
template <class T>
inline void hertz_force_stiffness_of(T contact, T overlap, T rest, T x, T& f, T& stiff) {
  const T d = ValueMath<T>::positive_part(overlap + x);
  const T s = ValueMath<T>::root(d);
  f = contact * d * s - rest;
  stiff = 1.5 * contact * s;
}

/// Hertz's curvature f'' = (3/4) A [Δ + x]_+^{−1/2} = K / (2 δ), from the stiffness K just
/// computed: no second square root, branch-free, 0 for an open contact (K = 0 there; unbounded as
/// a contact closes, where the orbit itself is only C¹). The tangent map's corrector needs it.
template <class T>
inline T hertz_curvature_of(T overlap, T x, T stiff) {
  return stiff / (2 * ValueMath<T>::at_least(overlap + x, std::numeric_limits<double>::min()));
}

/// The polynomial force c1 x + c2 x² + c3 x³ and its stiffness c1 + 2 c2 x + 3 c3 x².
template <class T>
inline T polynomial_force_of(T c1, T c2, T c3, T x) {
  return x * (c1 + x * (c2 + x * c3));
}
template <class T>
inline T polynomial_stiffness_of(T c1, T c2, T c3, T x) {
  return c1 + x * (2 * c2 + x * 3 * c3);
}
/// Its curvature 2 c2 + 6 c3 x.
template <class T>
inline T polynomial_curvature_of(T c2, T c3, T x) {
  return 2 * c2 + 6 * c3 * x;
}

/// The restoring force k_n u + q_n u³ [N] of bead n's on-site spring (the force is its negative),
/// its stiffness k_n + 3 q_n u² [N/m] and curvature 6 q_n u [N/m²], for kernels compiled with
/// (`quartic`) or without the quartic part; without it they read k alone (q may be null) and are
/// the expressions the linear springs always had.
template <bool quartic>
inline double onsite_restoring(const double* k, const double* q, std::size_t n, double u) {
  return onsite_restoring_of<quartic>(k[n], quartic ? q[n] : 0.0, u);
}
template <bool quartic>
inline double onsite_hessian(const double* k, const double* q, std::size_t n, double u) {
  return onsite_hessian_of<quartic>(k[n], quartic ? q[n] : 0.0, u);
}
inline double onsite_curvature(const double* q, std::size_t n, double u) { return onsite_curvature_of(q[n], u); }

class HertzLaw : public OnsiteSprings {
 public:
  explicit HertzLaw(const Chain& chain);

  struct View {
    const double* __restrict contact;
    const double* __restrict overlap;
    const double* __restrict rest;
    const double* onsite;          ///< k_n [N/m] per bead, null when the chain has no on-site springs
    const double* onsite_quartic;  ///< q_n [N/m³] per bead, null when the springs are linear
    double force(std::size_t k, double x) const { return hertz_force_of(contact[k], overlap[k], rest[k], x); }
    void force_stiffness(std::size_t k, double x, double& f, double& stiff) const {
      hertz_force_stiffness_of(contact[k], overlap[k], rest[k], x, f, stiff);
    }
  };
  View view() const { return {contact_.data(), overlap_.data(), rest_.data(), onsite_data(), onsite_quartic_data()}; }

  double force(std::size_t k, double x) const { return view().force(k, x); }
  double stiffness(std::size_t k, double x) const {
    double f, stiff;
    hertz_force_stiffness_of(contact_[k], overlap_[k], rest_[k], x, f, stiff);
    return stiff;
  }
  /// φ = (2/5) A [δ]_+^{5/2} − (2/5) A Δ^{5/2} − F0 x, with F0 the rest force of this bond
  /// (inline: the site energies' loop vectorizes with it).
  double potential(std::size_t k, double x) const {
    const double d = std::max(overlap_[k] + x, 0.0);
    return 0.4 * contact_[k] * d * d * std::sqrt(d) - rest_potential_[k] - rest_[k] * x;
  }
  double contact_force(std::size_t k, double x) const { return force(k, x) + rest_[k]; }
  std::size_t bonds() const { return contact_.size(); }

 private:
  std::vector<double> contact_, overlap_, rest_, rest_potential_;
};

/// Polynomial bond force f(x) = c1 x + c2 x² + c3 x³ (c2 = c3 = 0: linear). Needs F0 > 0, except
/// linear (degree 1) on a chain whose bonds are linear springs (Chain::spring): c1 = B_k then.
class PolynomialLaw : public OnsiteSprings {
 public:
  PolynomialLaw(const Chain& chain, int degree);

  struct View {
    const double* __restrict c1;
    const double* __restrict c2;
    const double* __restrict c3;
    const double* onsite;          ///< k_n [N/m] per bead, null when the chain has no on-site springs
    const double* onsite_quartic;  ///< q_n [N/m³] per bead, null when the springs are linear
    double force(std::size_t k, double x) const { return polynomial_force_of(c1[k], c2[k], c3[k], x); }
    void force_stiffness(std::size_t k, double x, double& f, double& stiff) const {
      f = force(k, x);
      stiff = polynomial_stiffness_of(c1[k], c2[k], c3[k], x);
    }
  };
  View view() const { return {c1_.data(), c2_.data(), c3_.data(), onsite_data(), onsite_quartic_data()}; }

  double force(std::size_t k, double x) const { return view().force(k, x); }
  double stiffness(std::size_t k, double x) const { return polynomial_stiffness_of(c1_[k], c2_[k], c3_[k], x); }
  double potential(std::size_t k, double x) const { return x * x * (c1_[k] / 2 + x * (c2_[k] / 3 + x * c3_[k] / 4)); }
  double contact_force(std::size_t k, double x) const { return precompression_ + force(k, x); }
  std::size_t bonds() const { return c1_.size(); }

 private:
  std::vector<double> c1_, c2_, c3_;
  double precompression_ = 0;
};

/// What an integrator needs from a force law.
template <class L>
concept BondForceLaw = requires(const L& law, std::size_t k, double x, double& out) {
  { law.force(k, x) } -> std::same_as<double>;
  { law.stiffness(k, x) } -> std::same_as<double>;
  { law.potential(k, x) } -> std::same_as<double>;
  { law.contact_force(k, x) } -> std::same_as<double>;
  { law.bonds() } -> std::same_as<std::size_t>;
  { law.onsite_potential(k, x) } -> std::same_as<double>;
  { law.view().onsite } -> std::convertible_to<const double*>;
  { law.view().onsite_quartic } -> std::convertible_to<const double*>;
  law.view().force_stiffness(k, x, out, out);
};

using ForceLaw = std::variant<HertzLaw, PolynomialLaw>;

/// Whether the law's beads have on-site springs.
inline bool grounded(const ForceLaw& law) {
  return std::visit([](const auto& l) { return l.grounded(); }, law);
}

/// The law of `kind` on this chain's bonds, with its on-site springs. Throws InvalidInput for
/// fpu/linear at F0 = 0, and for hertz/fpu on a chain whose bonds are linear springs.
ForceLaw make_force_law(ForceLawKind kind, const Chain& chain);

}  // namespace granular
