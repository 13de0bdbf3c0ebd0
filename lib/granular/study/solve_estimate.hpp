#pragma once
// How long a solve of every mode will take, said before it starts. LAPACK's dstevd with
// eigenvectors and the fast solver (twisted_ipr_solver.hpp) both run a minute or more at
// N ~ 2·10⁴ as one call that reports nothing until it returns. Their cost grows as N^p with p
// between 2 and 3 that depends on the chain (dstevd deflates the localized modes of a disordered
// chain: measured p ≈ 2.0 from 375 to 3,000 beads, ≈ 2.4 from 3,000 to 20,000), so no fixed law
// fits: the estimate times the same solve on the chain's first `sample` and 2·`sample` beads (the
// same matrix entries, on this machine, under its present load), takes p from the two, kept in
// [2, 3], and scales the larger block's time by (N/(2·sample))^p. A scale ("about a minute"), not
// a promise.
#include <cstddef>
#include <string>

#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"

namespace granular {

struct SolveEstimate {
  std::size_t beads = 0;         ///< N
  std::size_t sample_beads = 0;  ///< the larger block that was timed (2·sample); 0 when nothing was estimated
  double sample_seconds = 0;     ///< its wall time [s] (the faster of two)
  double power = 0;              ///< p from the two blocks' times, in [2, 3]
  double seconds = 0;            ///< sample_seconds·(N/sample_beads)^p [s]; 0 when nothing was estimated
};

/// Solves estimated to take longer than this [s] are announced (the tools' stderr line).
inline constexpr double announced_solve_seconds = 5;

/// The estimate for every mode of `d` by `config` (method lapack or fast, `selection` all modes),
/// from timed solves of its leading `sample` and 2·`sample` beads; nothing (seconds = 0) for
/// selected modes, another method, or N < 8·sample. The timing (each block twice) costs
/// 2(1 + 2^-p)(2·sample/N)^p of the solve it announces: at most 16 % at N = 8·sample with p = 2,
/// 4 % at 16·sample; below 8·sample the solve is short (4,000 beads: about a second).
SolveEstimate estimate_every_mode_solve(const DynamicalMatrix& d, const SpectrumConfig& config,
                                        const ModeSelection& selection, std::size_t sample = 500);

/// One line for stderr, e.g. "every mode of 20000 beads: about 100 s (1000 beads took 0.066 s; time
/// grows as N^2.4 here); no further progress until it ends".
std::string describe(const SolveEstimate& estimate);

}  // namespace granular
