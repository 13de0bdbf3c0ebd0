#pragma once
// Covariant Lyapunov vectors (CLVs) by Ginelli's forward–backward method (Ginelli, Poggi, Turchi,
// Chaté, Livi & Politi, PRL 99, 130601 (2007)). The Gram–Schmidt vectors of the Lyapunov spectrum
// (lyapunov_spectrum.hpp) depend on the metric and are not carried into each other by the
// dynamics; the CLVs are. The tangent map carries CLV_i(t) onto the direction of CLV_i(t + Δ), and
// CLV_i grows at the rate λ_i forward in time and shrinks at that rate backward.
//
// Forward phase: k vectors and a Householder QR every `orthonormalize_every` steps, M Q_r = Q_{r+1} R_r,
// first over `forward_transient` steps (the Q settle onto the Gram–Schmidt vectors), then over the
// window and `backward_transient` further steps, keeping every R_r and the Q at the sample times.
// Backward phase: from a random upper-triangular C at the end, C_r = R_r⁻¹ C_{r+1} (BLAS dtrsm),
// each column scaled to unit length; then CLV_i = Q C_i at the samples. C stays upper triangular,
// so span(CLV_1 … CLV_j) = span(Q_1 … Q_j). The column norms are the CLVs' stretch factors: over
// one interval CLV_i grows by 1/‖R⁻¹ c_i‖. Column i converges backwards as
// exp(−(λ_{i−1} − λ_i) T_b) (T_b: the time after the sample), so the backward transient must
// resolve the smallest gap of interest. Covariance itself holds at every sample by construction,
// converged or not.
//
// Memory: the stored factors are k(k+1)/2 doubles per QR, (window + backward_transient) /
// orthonormalize_every QRs (plus one per sample), and the Q and the results 2N k doubles per
// sample. The run is refused (InvalidInput naming `sample_steps`) before it starts if that exceeds
// config.memory_limit, by default half of what this process may use (detail::memory_limit()).
//
// Units: coordinates and norm as the Lyapunov exponents', w = (δu, t_unit δv), t_unit = 1 µs; a
// CLV is a State with δu in u [dimensionless direction, unit norm] and δv in v [1/s]. Growth
// rates and exponents [1/s]; angles [rad], which depend on the metric (t_unit); participation
// [beads], centre [bead index, 0-based], from the per-bead share of ‖w‖²,
// p_n = (δu_n² + (t_unit δv_n)²)/‖w‖².
//
//   auto clv = granular::covariant_vectors(law, chain, granular::saba2c(), 1e-7, start,
//                                          {.vectors = 4, .orthonormalize_every = 100},
//                                          {0, 10000, 20000});
//   clv.vectors[1][0];   // CLV_1 at the second sample
//   clv.growth_rates;    // ≈ λ_1 … λ_4
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "granular/dynamics/tangent_map.hpp"

namespace granular {

struct CovariantVectorsConfig {
  std::size_t vectors = 2;                  ///< k CLVs, the k most expanding, 1 ≤ k ≤ 2N
  std::size_t orthonormalize_every = 10;    ///< steps between QRs; each QR keeps one R (≥ 1)
  std::size_t forward_transient = 100000;   ///< steps before the window: the Q settle [steps]
  std::size_t backward_transient = 100000;  ///< steps after the last sample: C settles [steps]
  double time_unit = 1e-6;                  ///< t_unit of the norm [s]
  std::uint64_t seed = 1;                   ///< of the starting vectors (LyapunovSpectrum's) and of C
  double memory_limit = 0;                  ///< for the stored factors [bytes]; 0: half the process's
};

/// The CLVs at the sample times and their statistics; index s is the sample, i the CLV.
struct CovariantVectors {
  std::vector<std::uint64_t> steps;         ///< sample steps since the orbit's start
  std::vector<double> time;                 ///< sample times [s]
  std::vector<State> orbit;                 ///< the orbit's state at each sample (as the run's)
  std::vector<std::vector<State>> vectors;  ///< vectors[s][i] = CLV_{i+1}, unit norm in (δu, t_unit δv)
  /// Finite-time growth rates of the CLVs over the window, first sample to last [1/s]; zeros if
  /// the window is empty. They tend to the Lyapunov exponents.
  std::vector<double> growth_rates;
  /// The Gram–Schmidt exponents over the same window, Σ ln|R_jj| / window [1/s]: what
  /// LyapunovSpectrum gives for that stretch of the same orbit.
  std::vector<double> exponents;
  /// split_angles[s][j − 1]: the smallest angle between span(CLV_1 … CLV_j) and
  /// span(CLV_{j+1} … CLV_k), j = 1 … k − 1 [rad, 0 … π/2]. With j the number of positive exponents,
  /// the angle between the expanding and the other directions; near 0 signals near-tangencies.
  std::vector<std::vector<double>> split_angles;
  std::vector<std::vector<double>> participation;  ///< 1/Σ p_n² of each CLV [beads, 1 … N]
  std::vector<std::vector<double>> centre;         ///< Σ n p_n of each CLV [bead index]
  double stored_bytes = 0;                         ///< what the R's, Q's and results took [bytes]
};

/// Runs the orbit from `initial` (a plain run's first state) for forward_transient steps, then to
/// each of `sample_steps` (counted from the end of the forward transient, sorted), then
/// backward_transient steps more, and returns the k CLVs at the samples. The orbit is that of a
/// LyapunovSpectrum with the same vectors, interval and seed advanced by forward_transient, then
/// by the gaps between samples (the same bit for bit). Throws InvalidInput naming `vectors`,
/// `orthonormalize_every`, `time_unit`, `memory_limit`, `sample_steps` (empty, unsorted, or too much
/// memory) or the propagation's parameters; NumericalError if a vector degenerates.
CovariantVectors covariant_vectors(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                                   double time_step, const State& initial, const CovariantVectorsConfig& config,
                                   const std::vector<std::uint64_t>& sample_steps);

/// What covariant_vectors would keep at most for these settings [bytes] (the bound above), and the limit
/// it holds that to [bytes; config.memory_limit, or half of what the process may use] with the limit's
/// source: a front end refuses a run, naming its own keyword, before anything runs. Needs samples.
struct CovariantMemory {
  double bytes = 0, limit = 0;
  std::string source;
  bool fits() const { return !(limit > 0) || bytes <= limit; }
};
CovariantMemory covariant_memory(const CovariantVectorsConfig& config, std::size_t beads,
                                 const std::vector<std::uint64_t>& sample_steps);

/// The smallest principal angle between span(a) and span(b) [rad, 0 … π/2], in the norm
/// (δu, t_unit δv): atan2 of the smallest singular value of b's orthonormal basis with its part in
/// span(a) removed (the sine, accurate for small angles) and the largest of its projection (the
/// cosine). E.g. the angle between the unstable and stable subspaces of a full spectrum (k = 2N):
/// a = CLV_1 … CLV_{N−1}, b = CLV_{N+2} … CLV_{2N}. Throws InvalidInput naming `vectors` for an
/// empty, dependent or non-finite set or unequal sizes.
double smallest_subspace_angle(const std::vector<State>& a, const std::vector<State>& b, double time_unit = 1e-6);

}  // namespace granular
