#pragma once
// The twisted factorization of TwistedModeIpr (twisted_ipr_solver.hpp, step 2) for several
// shifts at once, and the one-shift reference it must reproduce bit for bit.
//
// For each shift σ: the stationary L D Lᵀ = T − σI from the top, the progressive U D Uᵀ from the
// bottom, the twist r minimizing |γ_r| = |D⁺_r − e_r U_r|, and z with z_r = 1 from the two
// bidiagonal recurrences (the three-term row of (T − σ) z = 0 across a tiny pivot), stopped once
// |z| < 1e-60; with the sums the IPR needs. The recurrences are serial in the bead index, not
// across shifts: `twisted_lanes` runs twisted_lane_count shifts in vector lanes (GCC/Clang vector
// extensions: GCC unrolled the former plain loops over 8 lanes and then left them scalar), the
// two factorizations in one loop and the z sweeps too, each lane masked until its own twist and
// after its own stop. Every lane does
// the same IEEE operations in the same order as `twisted_one` on its shift, so the results are
// identical (tests/linear/twisted_lanes_test.cpp).
#include <cstddef>
#include <vector>

namespace granular::detail {

/// Shifts per call of twisted_lanes: enough independent division chains to hide the division's
/// latency (4 AVX2 vectors per direction), and 3 N × 16 doubles of scratch still fit in L2.
inline constexpr std::size_t twisted_lane_count = 16;

/// One shift's result: |γ_r| and the sums over z (z_r = 1) and v = z ⊙ mass of Σz², Σv², Σv⁴.
struct TwistedSums {
  double gamma = 0, z2 = 0, v2 = 0, v4 = 0;
  std::size_t twist = 0;
};

/// Scratch of twisted_lanes: 3 N × lanes doubles, kept between calls.
struct TwistedLaneWork {
  std::vector<double> lplus, dplus, uminus;
  std::vector<unsigned char> node_up, node_down;  // rows where some lane crosses a node
  void reserve(std::size_t n);
};

/// T (diagonal d, off-diagonal e, n ≥ 2) − sigma[l] for l < twisted_lane_count; `mass` weights v.
void twisted_lanes(const double* d, const double* e, const double* mass, std::size_t n, const double* sigma,
                   TwistedLaneWork& work, TwistedSums* out);

/// The same for one shift, scalar: the reference the lanes reproduce. `work`: 3 n doubles.
TwistedSums twisted_one(const double* d, const double* e, const double* mass, std::size_t n, double sigma,
                        std::vector<double>& work);

}  // namespace granular::detail
