#pragma once
// e^x − 1 for x ≤ 0 in a form the compiler vectorizes: no library call, no branch, so a loop over
// bonds runs it in every lane (std::expm1 is a scalar call that keeps the damped step's bond loop
// scalar). At most 0.81 ulp from the exact value on x ≤ 0, measured against long double
// (glibc's expm1: 0.75 ulp; tests/dynamics/vector_expm1_test.cpp asserts ≤ 1).
#include <bit>
#include <cstddef>
#include <cstdint>
#include <initializer_list>

namespace granular::detail {

/// p(r) = Σ r^j/(j + 2)!, j = 0 … 11, by Horner: e^r − 1 = r + r² p(r) to r^13, whose tail
/// r^14/14! is below 1e-17 of r for |r| ≤ 0.35. (Estrin's shorter chain measured no faster in the
/// damped step and lost accuracy: 0.90 ulp.)
inline double expm1_taylor_tail(double r) {
  double p = 1.0 / 6227020800.0;  // 1/13!
  for (const double inverse_factorial : {1.0 / 479001600, 1.0 / 39916800, 1.0 / 3628800, 1.0 / 362880, 1.0 / 40320,
                                         1.0 / 5040, 1.0 / 720, 1.0 / 120, 1.0 / 24, 1.0 / 6, 1.0 / 2})
    p = p * r + inverse_factorial;
  return p;
}

/// e^x − 1 for x ≤ 0 (−1 below −745, where e^x underflows; NaN in, NaN out), with no cancellation
/// for small |x|. x > 0 is outside its domain: it gives 0.
inline double expm1_nonpositive(double x) {
  constexpr double ln2_hi = 6.93147180369123816490e-01;  // Cody–Waite split of ln 2: k·ln2_hi is exact
  constexpr double ln2_lo = 1.90821492927058770002e-10;
  constexpr double inv_ln2 = 1.44269504088896338700e+00;
  // Clamped into [−745, 0], NaN to −745: keeps 2^k a normal number's exponent (k ≥ −1075) and the
  // conversion of k to an integer defined (NaN or ±∞ there is undefined behaviour).
  const double xc = x >= -745.0 ? (x <= 0.0 ? x : 0.0) : -745.0;
  const double k = __builtin_nearbyint(xc * inv_ln2);                     // x = k ln 2 + r, |r| ≤ ln2/2 (+ rounding)
  const double hi = xc - k * ln2_hi, lo = k * ln2_lo;                     // hi exact
  const double r = hi - lo, c = (hi - r) - lo;                            // x = k ln 2 + r + c: c is r's rounding
  const double em1 = r + (r * r * expm1_taylor_tail(r) + c * (1.0 + r));  // e^(r + c) − 1 to first order in c
  // e^x − 1 = 2^k (e^r − 1) + (2^k − 1); 2^k − 1 is exact for k ≥ −53 and −1 to rounding below.
  // 2^k is built in two halves so that k down to −1075 stays a normal number's exponent.
  const auto half = static_cast<std::int64_t>(k) / 2;
  const double two_a = std::bit_cast<double>((half + 1023) << 52);
  const double two_b = std::bit_cast<double>((static_cast<std::int64_t>(k) - half + 1023) << 52);
  const double two_k = two_a * two_b;
  const double out = (two_k - 1.0) + two_k * em1;
  return x != x || x == 0 ? x : out;  // NaN; ±0 keeps its sign, as expm1's does
}

/// The bound of expm1_unreduced_nonpositive's domain: x · (1/ln 2) ≥ −0.4905 rounds to k = 0.
inline constexpr double expm1_unreduced_bound = -0.34;

/// e^x − 1 for −0.34 ≤ x ≤ 0 (outside: not e^x − 1): expm1_nonpositive with the range reduction
/// left out, which there is the identity (k = 0, r = x, c = 0), so the same bits for a third less
/// work.
inline double expm1_unreduced_nonpositive(double x) {
  const double out = x + (x * x * expm1_taylor_tail(x));
  return x == 0 ? x : out;
}

/// e^x − 1 for −1/16 ≤ x ≤ 0 (outside: not e^x − 1): expm1_nonpositive's formula with k = 0, which
/// it is there, and its Taylor series cut at x^9, whose tail x^10/10! is below 4e-18 of x for
/// |x| ≤ 1/16 — a quarter of the work. Within one ulp, as expm1_nonpositive
/// (tests/dynamics/vector_expm1_test.cpp).
inline double expm1_small_nonpositive(double x) {
  double p = 1.0 / 362880;  // 1/9!
  for (const double inverse_factorial : {1.0 / 40320, 1.0 / 5040, 1.0 / 720, 1.0 / 120, 1.0 / 24, 1.0 / 6, 1.0 / 2})
    p = p * x + inverse_factorial;
  const double out = x + x * x * p;
  return x == 0 ? x : out;
}

/// The bound of expm1_small_nonpositive's domain.
inline constexpr double expm1_small_bound = -1.0 / 16;

/// a[i] ← e^{a[i]} − 1 for a[i] ≤ 0, i < n: by expm1_small_nonpositive when every a[i] is in its
/// domain (contact damping's usual arguments, −2y with y = hλ/2 ≪ 1), else by
/// expm1_unreduced_nonpositive when every a[i] is in its, else by expm1_nonpositive (the last two
/// give the same bits). The choice is per call, so a value may differ in its last bit with the
/// other values of the call (each is within one ulp of e^x − 1); every loop vectorizes.
inline void expm1_nonpositive(double* a, std::size_t n) {
  unsigned beyond_small = 0, beyond_unreduced = 0;  // integer ORs, which GCC vectorizes
  for (std::size_t i = 0; i < n; ++i) {
    beyond_small |= a[i] >= expm1_small_bound ? 0u : 1u;  // NaN: beyond both
    beyond_unreduced |= a[i] >= expm1_unreduced_bound ? 0u : 1u;
  }
  if (beyond_small == 0)
    for (std::size_t i = 0; i < n; ++i) a[i] = expm1_small_nonpositive(a[i]);
  else if (beyond_unreduced == 0)
    for (std::size_t i = 0; i < n; ++i) a[i] = expm1_unreduced_nonpositive(a[i]);
  else
    for (std::size_t i = 0; i < n; ++i) a[i] = expm1_nonpositive(a[i]);
}

}  // namespace granular::detail
