#pragma once
// The native vector of doubles that the lane-batched kernels (linear/detail/twisted_lanes.cpp,
// rational_ql.cpp; lanes/detail/lane_kernels.hpp) are written in: GCC/Clang vector extensions as wide as this build's
// CPU has (generic vectors wider than the hardware's were lowered element by element through the stack: 3× slower than
// scalar code). Vectors are only ever locals or references, so no calling convention depends on
// their width.
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

#include <cmath>
#include <cstddef>
#include <cstring>

namespace granular::detail::lanes {

#if defined(__AVX512F__)
inline constexpr std::size_t W = 8;
#elif defined(__AVX__)
inline constexpr std::size_t W = 4;
#else
inline constexpr std::size_t W = 2;
#endif
typedef double V __attribute__((vector_size(W * sizeof(double))));
typedef long M __attribute__((vector_size(W * sizeof(long))));
static_assert(sizeof(long) == sizeof(double));

// memcpy: an unaligned load or store on every compiler (Clang ignored aligned(8) on the vector
// typedef and emitted aligned moves)
inline V load(const double* p) {
  V x;
  std::memcpy(&x, p, sizeof x);
  return x;
}
inline void store(double* p, const V& x) { std::memcpy(p, &x, sizeof x); }

/// √x in every lane, correctly rounded as std::sqrt (a loop over the lanes stays scalar in GCC).
inline V root(const V& x) {
#if defined(__AVX512F__)
  // The masked form with every lane set: GCC 12's _mm512_sqrt_pd passes an "undefined" vector
  // that its own -Wuninitialized then flags.
  return (V)_mm512_mask_sqrt_pd((__m512d)x, static_cast<__mmask8>(0xFF), (__m512d)x);
#elif defined(__AVX__)
  return (V)_mm256_sqrt_pd((__m256d)x);
#elif defined(__SSE2__)
  return (V)_mm_sqrt_pd((__m128d)x);
#else
  V out;
  for (std::size_t w = 0; w < W; ++w) out[w] = std::sqrt(x[w]);
  return out;
#endif
}

/// max(x, 0) in every lane, as std::max(x, 0.0) gives it: −0 stays −0, NaN stays NaN.
inline V positive_part(const V& x) { return x < 0 ? V{} : x; }

/// The lanes of `yes` where `mask` is set, of `no` elsewhere.
inline V select(const M& mask, const V& yes, const V& no) { return mask ? yes : no; }

/// |x| in every lane.
inline V vabs(const V& x) { return (V)((M)x & 0x7fffffffffffffffL); }

/// Whether any lane of any of the K masks is set.
template <std::size_t K>
bool any(const M (&mask)[K]) {
  M acc = mask[0];
  for (std::size_t h = 1; h < K; ++h) acc |= mask[h];
  long out = 0;
  for (std::size_t w = 0; w < W; ++w) out |= acc[w];
  return out != 0;
}

}  // namespace granular::detail::lanes
