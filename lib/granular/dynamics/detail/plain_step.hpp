#pragma once
// One unmerged step of a drift–kick scheme on the whole chain, for the propagators that do
// something between steps (damping) or beside them (the tangent map). The conservative
// stepper (splitting_propagator.cpp) merges drifts and correctors across steps and runs
// blocked kernels over an active window; this one keeps each step self-contained, so another
// flow can be composed at the step boundaries. Same arithmetic per bead as the fast stepper.
//
// Arrays are padded: up[i+1] is bead i, up[0] = up[N+1] = 0 the walls; bond k strains
// up[k] − up[k+1]; ap is padded like up (ap[0] = ap[N+1] = 0).
#include <cstddef>

#include "granular/dynamics/scheme.hpp"

namespace granular::detail {

inline void plain_drift(double* __restrict up, const double* __restrict v, std::size_t n, double d) {
  for (std::size_t i = 0; i < n; ++i) up[i + 1] += d * v[i];
}

template <class View>
void plain_kick(const View law, const double* __restrict up, double* __restrict f, double* __restrict v,
                const double* __restrict im, std::size_t n, double h) {
  for (std::size_t k = 0; k <= n; ++k) f[k] = law.force(k, up[k] - up[k + 1]);
  for (std::size_t i = 0; i < n; ++i) v[i] += h * im[i] * (f[i] - f[i + 1]);
}

/// The SABA2C corrector kick with coefficient c (SPEC §4); leaves f, stiff and a (padded) for a
/// tangent map to reuse.
template <class View>
void plain_correct(const View law, const double* __restrict up, double* __restrict f, double* __restrict stiff,
                   double* __restrict ap, double* __restrict v, const double* __restrict im, std::size_t n, double c) {
  for (std::size_t k = 0; k <= n; ++k) law.force_stiffness(k, up[k] - up[k + 1], f[k], stiff[k]);
  for (std::size_t i = 0; i < n; ++i) ap[i + 1] = im[i] * (f[i] - f[i + 1]);
  for (std::size_t i = 0; i < n; ++i)
    v[i] += c * im[i] * (stiff[i] * (ap[i] - ap[i + 1]) - stiff[i + 1] * (ap[i + 1] - ap[i + 2]));
}

/// Work arrays of a plain step.
struct PlainWork {
  double* f;      ///< N+1 bond forces
  double* stiff;  ///< N+1 bond stiffnesses
  double* ap;     ///< N+2, padded accelerations, ends 0
};

/// [corrector g τ³] D(a_0 τ) K(b_0 τ) … K(b_{s−1} τ) D(a_s τ) [corrector g τ³]
template <class View>
void plain_step(const View law, const SplittingScheme& s, double* up, double* v, const double* im, std::size_t n,
                double tau, const PlainWork& w) {
  const double g = s.corrector * tau * tau * tau;
  if (g != 0) plain_correct(law, up, w.f, w.stiff, w.ap, v, im, n, g);
  for (std::size_t j = 0; j < s.kick.size(); ++j) {
    plain_drift(up, v, n, s.drift[j] * tau);
    plain_kick(law, up, w.f, v, im, n, s.kick[j] * tau);
  }
  plain_drift(up, v, n, s.drift.back() * tau);
  if (g != 0) plain_correct(law, up, w.f, w.stiff, w.ap, v, im, n, g);
}

}  // namespace granular::detail
