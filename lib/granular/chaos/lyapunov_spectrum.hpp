#pragma once
// The k largest Lyapunov exponents of a chain's orbit by the tangent map with k deviation vectors
// (Benettin, Galgani, Giorgilli & Strelcyn, Meccanica 15, 9 (1980); Skokos, Lect. Notes Phys. 790,
// 63 (2010)): the vectors ride the same splitting scheme as the orbit (tangent_map.hpp), and every
// `orthonormalize_every` steps they are replaced by the Q of a Householder QR factorization
// (LAPACK dgeqrf/dorgqr) of the matrix they form, ln|R_jj| added to the running sum S_j; the
// finite-time exponent is λ_j(t) = S_j(t)/t. With k = 2N the sum of all of them is the log of the
// volume growth, zero for a Hamiltonian (symplectic) map, and they come in pairs λ_j = −λ_{2N+1−j}.
//
// Coordinates and norm as the maximal exponent's: w = (δu, t_unit δv), t_unit = 1 µs (the
// exponents do not depend on it; the orthonormality does).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "granular/dynamics/tangent_map.hpp"

namespace granular {

struct LyapunovSpectrumConfig {
  std::size_t vectors = 2;                ///< k deviation vectors, 1 ≤ k ≤ 2N
  std::size_t orthonormalize_every = 10;  ///< steps between QR re-orthonormalizations (≥ 1)
  double time_unit = 1e-6;                ///< t_unit of the norm [s]
  std::uint64_t seed = 1;                 ///< of the random orthonormal starting vectors
};

class LyapunovSpectrum {
 public:
  /// Starts the orbit at `initial` (the plain run's first state) and k random orthonormal vectors.
  /// Throws InvalidInput naming `vectors`, `orthonormalize_every` or the propagation's parameters.
  LyapunovSpectrum(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme, double time_step,
                   const State& initial, const LyapunovSpectrumConfig& config);
  LyapunovSpectrum(const LyapunovSpectrum&) = delete;  // the map calls back into this object
  LyapunovSpectrum& operator=(const LyapunovSpectrum&) = delete;

  /// Advances `steps` steps of τ, re-orthonormalizing every config.orthonormalize_every steps of
  /// the run (between steps, inside the map: the orbit is a plain run's advanced by the same calls)
  /// and at the end, so that the exponents are current.
  void advance(std::size_t steps);

  /// λ_1(t) … λ_k(t) [1/s], in the order of the vectors (the QR keeps the largest growth first;
  /// finite-time values need not be sorted); zeros at t = 0.
  std::vector<double> exponents() const;
  /// The orthonormal vectors now (k of them, N beads each; δv in 1/s: its norm counts t_unit δv).
  std::vector<State> vectors() const;
  /// The orbit's state and time, the same bit for bit as a plain run's of the scheme.
  State state() const { return tangent_->state(); }
  double time() const { return tangent_->time(); }

  /// From now on, `record` sees the R of every re-orthonormalization (k × k, column-major, zeros
  /// below the diagonal; V = Q R with V the vectors before it), as covariant Lyapunov vectors need
  /// (covariant_vectors.hpp). Empty: none. It changes no arithmetic: the orbit and the vectors are
  /// the same with or without it.
  void record_factors(std::function<void(std::span<const double> r)> record);

 private:
  void orthonormalize();
  void factorize();  ///< the vectors' matrix becomes Q, diagonal_ the diagonal of R

  std::unique_ptr<TangentPropagator> tangent_;
  LyapunovSpectrumConfig config_;
  std::size_t beads_;
  std::vector<double> sums_;                                      ///< S_j
  std::uint64_t orthonormalized_at_ = 0;                          ///< the step of the last QR
  std::vector<double> matrix_, tau_, work_, diagonal_, du_, dv_;  ///< the QR's buffers, LAPACK's workspace
  std::function<void(std::span<const double>)> record_;           ///< record_factors'
  std::vector<double> factor_;                                    ///< the last R, for record_
};

/// λ_1 … λ_k of a LyapunovSpectrum run at the given sample steps (sorted, from 0: step 0 gives
/// zeros), and with k ≥ 2 GALI_2 … GALI_k and SALI of its starting vectors carried along without
/// orthonormalization (FactorAlignment of its R's, alignment_indices.hpp: no second orbit).
struct LyapunovSeries {
  std::vector<double> time;                    ///< [s]
  std::vector<std::vector<double>> exponents;  ///< exponents[s][j] = λ_{j+1}(time[s]) [1/s]
  std::vector<std::vector<double>> gali;       ///< gali[s][j] = GALI_{j+2}(time[s]); empty for k = 1
  std::vector<double> sali;                    ///< SALI(time[s]); empty for k = 1
};
LyapunovSeries lyapunov_series(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme, double time_step,
                               const State& initial, const LyapunovSpectrumConfig& config,
                               const std::vector<std::uint64_t>& sample_steps);

}  // namespace granular
