#pragma once
// The Sturm (inertia) count of a symmetric tridiagonal T: how many eigenvalues lie strictly below
// σ, the negative pivots of T − σI = L D Lᵀ (Sylvester's law of inertia), with the pivot guard of
// LAPACK's bisection (dstebz). One kernel for every scalar count: TridiagonalOperator::count_below
// (one shift) and the many-shift sweeps of sturm_bisection.cpp (L shifts per sweep; the loop over
// the lanes is what the compiler vectorizes). An AVX-512 build's sweeps use their own kernel
// there, whose division is a refined reciprocal.
#include <algorithm>
#include <cmath>
#include <limits>

#include "granular/linear/sym_tridiagonal.hpp"

namespace granular::detail {

/// dstebz's guard: a pivot no larger than this in magnitude is replaced by −pivmin, so a zero
/// pivot counts as negative and the next division stays finite.
inline double sturm_pivot_floor(const SymTridiagonal& t) {
  double max_e2 = 1;
  for (double e : t.off_diagonal) max_e2 = std::max(max_e2, e * e);
  return std::numeric_limits<double>::min() * max_e2;
}

/// count[j] = the eigenvalues of `t` (not empty) below shift[j], j < L, in one sweep.
template <int L>
void sturm_counts(const SymTridiagonal& t, double pivmin, const double* shift, long* count) {
  const std::size_t n = t.size();
  const double* a = t.diagonal.data();
  const double* b = t.off_diagonal.data();
  double p[L], s[L], c[L];
  for (int j = 0; j < L; ++j) {
    s[j] = shift[j];
    double q = a[0] - s[j];
    q = std::fabs(q) <= pivmin ? -pivmin : q;  // a zero pivot counts as negative
    p[j] = q;
    c[j] = q < 0 ? 1.0 : 0.0;
  }
  for (std::size_t i = 1; i < n; ++i) {
    const double ai = a[i], b2 = b[i - 1] * b[i - 1];
#if defined(__GNUC__) && !defined(__clang__)  // clang warns about the GCC pragma (included in several files)
#pragma GCC ivdep
#endif
    for (int j = 0; j < L; ++j) {
      double q = (ai - s[j]) - b2 / p[j];
      q = std::fabs(q) <= pivmin ? -pivmin : q;
      p[j] = q;
      c[j] += q < 0 ? 1.0 : 0.0;
    }
  }
  for (int j = 0; j < L; ++j) count[j] = static_cast<long>(c[j]);
}

#if defined(__GNUC__)
/// Four shifts' pivots side by side (GCC/Clang vector extensions; the compiler left the loop over
/// lanes above scalar for 8 and 16 lanes): the vector sweeps of sturm_bisection.cpp (counts) and
/// localized_modes.cpp (mode anchors) guard their pivots with sturm_guard, as sturm_counts does,
/// and compute them with its arithmetic, so their counts equal its counts.
using SturmLanes = double __attribute__((vector_size(32)));
using SturmMasks = long long __attribute__((vector_size(32)));  ///< lane masks: −1 true, 0 false

/// dstebz's guard per lane: a pivot q with |q| ≤ pivmin becomes −pivmin (counts as negative).
inline SturmLanes sturm_guard(SturmLanes q, SturmLanes pivmin) {
  const SturmLanes zero{};
  const SturmLanes mag = q < zero ? -q : q;
  return mag <= pivmin ? -pivmin : q;
}
#endif

}  // namespace granular::detail
