#pragma once
// Every eigenvalue of a symmetric tridiagonal matrix by the root-free (Pal–Walker–Kahan) QL
// iteration with Wilkinson shifts: the algorithm of LAPACK's dsterf, O(N²), absolute accuracy
// ~ε‖T‖. It is written here rather than called because one QL step is a serial chain of
// divisions (~40 cycles of latency for two or three flops of work): one chain leaves the divider
// idle most of the time, while independent chains are independent latency chains.
// `rational_ql_lanes` runs ql_lane_count chains' sweeps side by side in vector lanes, each lane
// taking the next chain of the batch as soon as its own is done. Every lane does the IEEE
// operations of `rational_ql` in the same order, so each chain's eigenvalues are the same bit for
// bit alone, in lanes, or in any batch (tests/linear/rational_ql_test.cpp).
#include <cstddef>
#include <span>
#include <vector>

namespace granular::detail {

/// One matrix: diagonal d (n entries) and squared off-diagonal e2 (n − 1 entries), both
/// overwritten; the eigenvalues end up in d, unsorted.
struct QlChain {
  double* d = nullptr;
  double* e2 = nullptr;
  std::size_t n = 0;
  bool converged = false;  ///< set by the solvers: false after more than 30 n QL iterations
};

/// One chain, scalar: the reference the lanes reproduce.
void rational_ql(QlChain& chain);

/// Lanes of rational_ql_lanes: enough independent division chains to hide the division's latency
/// (two AVX-512 vectors, four AVX2 ones).
inline constexpr std::size_t ql_lane_count = 16;

/// Scratch of rational_ql_lanes (two rings of n_max × ql_lane_count doubles), kept between calls.
struct QlLaneWork {
  std::vector<double> d, e2;
};

/// Every chain of `chains`, ql_lane_count at a time; results identical to rational_ql's.
void rational_ql_lanes(std::span<QlChain> chains, QlLaneWork& work);

}  // namespace granular::detail
