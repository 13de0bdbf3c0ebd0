#pragma once
// The blocked drift–kick kernels of the conservative stepper (docs/physics.md, "Nonlinear dynamics"), shared with the damped
// stepper (damping.cpp), which runs the same kicks between its damping substeps. Hot loops:
// per-bond arrays, 1/m per bead, branch-free [x]_+, restrict pointers, no allocation.
#include <algorithm>
#include <cstddef>

#include "granular/dynamics/force_law.hpp"

namespace granular::detail {

// The kernels are free functions because GCC honours __restrict on parameters, not on locals
// inside member functions (there it versions the loops for aliasing and gives up).
//
// Each kick or corrector runs block by block: the bond pass (bound by the sqrt unit), then the
// bead pass (velocity and the drift that follows), on 256 bonds whose arrays stay in L1. One
// fused loop would read f[k−1] right after storing f[k] as part of a vector, which defeats
// store forwarding and runs 2× slower. A bead is updated once both its bond forces are known
// and its position is no longer needed by a bond of a later block.
constexpr std::size_t block = 256;

// v += h F/m, then u += d v. u is padded: u[k] is bead k−1, u[0] and u[N+1] the walls; bond k
// strains u[k] − u[k+1]. Bond k's block updates bead k−1. With on-site springs (`grounded`, ks the
// per-bead k_n, qs the q_n when `quartic`) F of bead k−1 also holds −k u[k] (− q u[k]³), read
// before the drift moves u[k].
template <bool grounded, bool quartic, class View>
void kick_and_drift_with(const View law, const double* __restrict ks, const double* __restrict qs, double* __restrict u,
                         double* __restrict f, double* __restrict v, const double* __restrict im, std::size_t lo,
                         std::size_t hi, double h, double d) {
  f[lo] = law.force(lo, u[lo] - u[lo + 1]);
  for (std::size_t b0 = lo + 1; b0 <= hi; b0 += block) {
    const std::size_t b1 = std::min(hi + 1, b0 + block);
    for (std::size_t k = b0; k < b1; ++k) f[k] = law.force(k, u[k] - u[k + 1]);
    for (std::size_t k = b0; k < b1; ++k) {
      double force = f[k - 1] - f[k];
      if constexpr (grounded) force -= onsite_restoring<quartic>(ks, qs, k - 1, u[k]);
      v[k - 1] += h * im[k - 1] * force;
      u[k] += d * v[k - 1];
    }
  }
}

template <class View>
void kick_and_drift(const View law, double* __restrict u, double* __restrict f, double* __restrict v,
                    const double* __restrict im, std::size_t lo, std::size_t hi, double h, double d) {
  if (law.onsite_quartic)
    kick_and_drift_with<true, true>(law, law.onsite, law.onsite_quartic, u, f, v, im, lo, hi, h, d);
  else if (law.onsite) kick_and_drift_with<true, false>(law, law.onsite, nullptr, u, f, v, im, lo, hi, h, d);
  else kick_and_drift_with<false, false>(law, nullptr, nullptr, u, f, v, im, lo, hi, h, d);
}

// docs/physics.md, "Nonlinear dynamics" corrector: v_i += (c/m_i) [K_i (a_{i−1} − a_i) + K_{i+1} (a_{i+1} − a_i)], a =
// F/m, walls a = 0; then u += d v. Bond k's block computes a of bead k−1 and updates bead k−2, which needs a_{k−1}. a
// is padded like u (a[i+1] is bead i); a[lo] and a[hi+1] are never written and stay 0. On-site springs add −k_i u_i
// to F_i and −k_i to the Hessian's diagonal, hence −k_i a_i in the bracket; a quartic part adds −q_i u_i³ and
// −3 q_i u_i², at u_i before its drift (the bead's drift follows its bracket).
template <bool grounded, bool quartic, class View>
void correct_and_drift_with(const View law, const double* __restrict ks, const double* __restrict qs,
                            double* __restrict u, double* __restrict f, double* __restrict stiff, double* __restrict a,
                            double* __restrict v, const double* __restrict im, std::size_t lo, std::size_t hi, double c,
                            double d) {
  // Written out rather than through lambdas: GCC keeps __restrict on parameters only.
  law.force_stiffness(lo, u[lo] - u[lo + 1], f[lo], stiff[lo]);
  law.force_stiffness(lo + 1, u[lo + 1] - u[lo + 2], f[lo + 1], stiff[lo + 1]);
  double first = f[lo] - f[lo + 1];
  if constexpr (grounded) first -= onsite_restoring<quartic>(ks, qs, lo, u[lo + 1]);
  a[lo + 1] = im[lo] * first;
  for (std::size_t b0 = lo + 2; b0 <= hi; b0 += block) {
    const std::size_t b1 = std::min(hi + 1, b0 + block);
    for (std::size_t k = b0; k < b1; ++k) law.force_stiffness(k, u[k] - u[k + 1], f[k], stiff[k]);
    for (std::size_t k = b0; k < b1; ++k) {
      double force = f[k - 1] - f[k];  // bead k−1, before it drifts
      if constexpr (grounded) force -= onsite_restoring<quartic>(ks, qs, k - 1, u[k]);
      a[k] = im[k - 1] * force;
    }
    for (std::size_t k = b0; k < b1; ++k) {
      const std::size_t i = k - 2;
      double g = stiff[i] * (a[i] - a[i + 1]) - stiff[i + 1] * (a[i + 1] - a[k]);
      if constexpr (grounded) g -= onsite_hessian<quartic>(ks, qs, i, u[i + 1]) * a[i + 1];
      v[i] += c * im[i] * g;
      u[i + 1] += d * v[i];
    }
  }
  const std::size_t i = hi - 1;  // the last bead: a[hi+1] (beyond the window, or the wall) is 0
  double g = stiff[i] * (a[i] - a[i + 1]) - stiff[i + 1] * (a[i + 1] - a[i + 2]);
  if constexpr (grounded) g -= onsite_hessian<quartic>(ks, qs, i, u[i + 1]) * a[i + 1];
  v[i] += c * im[i] * g;
  u[i + 1] += d * v[i];
}

template <class View>
void correct_and_drift(const View law, double* __restrict u, double* __restrict f, double* __restrict stiff,
                       double* __restrict a, double* __restrict v, const double* __restrict im, std::size_t lo,
                       std::size_t hi, double c, double d) {
  if (law.onsite_quartic)
    correct_and_drift_with<true, true>(law, law.onsite, law.onsite_quartic, u, f, stiff, a, v, im, lo, hi, c, d);
  else if (law.onsite)
    correct_and_drift_with<true, false>(law, law.onsite, nullptr, u, f, stiff, a, v, im, lo, hi, c, d);
  else correct_and_drift_with<false, false>(law, nullptr, nullptr, u, f, stiff, a, v, im, lo, hi, c, d);
}

inline void drift_only(double* __restrict u, const double* __restrict v, std::size_t lo, std::size_t hi, double d) {
  for (std::size_t i = lo; i < hi; ++i) u[i + 1] += d * v[i];
}

}  // namespace granular::detail
