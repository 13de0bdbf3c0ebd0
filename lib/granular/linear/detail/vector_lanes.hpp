#pragma once
// The native vector of doubles that the lane-batched kernels (twisted_lanes.cpp, rational_ql.cpp)
// are written in: GCC/Clang vector extensions as wide as this build's CPU has (generic vectors
// wider than the hardware's were lowered element by element through the stack: 3× slower than
// scalar code). Vectors are only ever locals or references, so no calling convention depends on
// their width.
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
