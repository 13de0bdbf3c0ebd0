#pragma once
// Transfer matrices of the linearized chain (docs/physics.md, "Infinite chains"). At angular frequency
// ω the equations of motion give the recursion
//     u_{n+1} = [(B_n + B_{n+1} + k_n − m_n ω²) u_n − B_n u_{n−1}] / B_{n+1},   u_0 = 0, u_1 = 1
// (beads n = 1 … N, bond n to the left of bead n, u_0 and u_{N+1} at the walls; k_n the on-site
// spring of bead n, BeadSource::read_onsite, 0 for every chain but S1). Two numbers
// come out of one walk along the chain:
//  - the Lyapunov exponent λ = (1/N) ln ‖(u_{N+1}, u_N)‖ [1/bead], the inverse localization
//    length of the infinite chain as N → ∞ (ℓ = 1/λ beads);
//  - the number of sign changes of u_1 … u_{N+1}, which equals the number of eigenfrequencies
//    of the finite chain (fixed walls) below ω, exactly (Dean's method: the ratios
//    B_{n+1} u_{n+1}/u_n are the pivots of the LDLᵀ factorization of K − ω² M, and Sylvester's
//    law of inertia counts the negative ones).
//
// The chain is read a piece at a time from a BeadSource (memory O(frequencies), not O(N)); a
// block of frequencies walks it together, one frequency per vector lane; OpenMP threads take
// whole blocks. Results are bit-identical for any thread count: each frequency's arithmetic
// does not depend on which block or thread holds it, and renormalization is by exact powers of
// two at positions fixed by the bead index.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "granular/model/bead_source.hpp"

namespace granular {

struct TransferMatrixConfig {
  /// The chain is cut into this many consecutive segments (at most N) for the statistical error
  /// of λ; ≥ 2.
  std::size_t segments = 32;
  int threads = 0;  ///< OpenMP threads over frequency blocks; 0 = OMP_NUM_THREADS if set, else every core
  /// Called from any thread (must be thread-safe) with the number of bead × frequency steps
  /// just done; the total is N × frequencies.
  std::function<void(std::size_t)> progress;
};

struct TransferMatrixScan {
  std::vector<double> frequency_khz;  ///< as given [kHz]
  std::vector<double> lyapunov;       ///< λ [1/bead]
  /// Standard error of λ from the segments (batch means): the segment exponents
  /// λ_s = (growth of ln‖(u_{n+1}, u_n)‖ over segment s) / (its length) have mean λ (up to
  /// the ±1-bead differences of segment lengths), and the error is
  /// sqrt(Σ_s (λ_s − mean)² / (S (S − 1))). Valid when segments are much longer than ℓ (they
  /// are then nearly independent); for λ ≈ 0 (inside a band) it measures the O(1/segment)
  /// oscillation instead.
  std::vector<double> lyapunov_error;
  std::vector<std::int64_t> modes_below;  ///< eigenfrequencies of the finite chain < f (exact)
  std::size_t beads = 0;                  ///< N
  std::size_t segments = 0;               ///< S actually used
};

/// λ, its error and the node count at every frequency (kHz, finite, ≥ 0, any order).
/// Throws InvalidInput naming `frequencies` or `segments`, NumericalError if the recursion
/// overflows (a frequency absurdly far above the bands).
TransferMatrixScan transfer_matrix_scan(const BeadSource& chain, const std::vector<double>& frequency_khz,
                                        const TransferMatrixConfig& config = {});

}  // namespace granular
