#pragma once
// The alignment indices of deviation vectors, chaos indicators that tell chaotic from regular
// orbits (docs/beyond-the-paper.md, "GALI and SALI"):
//
// - GALI_k (Skokos, Bountis & Antonopoulos, Physica D 231, 30 (2007)): the volume of the
//   parallelepiped spanned by k deviation vectors each scaled to unit length, i.e. the product
//   of the singular values of the 2N × k matrix of the unit vectors; 1 for orthogonal vectors,
//   0 when they are linearly dependent. Computed here as |Π R_jj| of the Householder QR of that
//   matrix (LAPACK dgeqrf), which equals the product of the singular values; the leading j × j
//   block of R gives GALI_j for every j ≤ k from the one factorization.
// - SALI (Skokos, J. Phys. A 34, 10029 (2001)): min(‖ŵ1 + ŵ2‖, ‖ŵ1 − ŵ2‖) of two unit vectors,
//   between 0 (parallel or antiparallel) and √2 (orthogonal); it behaves like GALI_2.
//
// On a chaotic orbit every vector turns towards the most unstable direction and
// GALI_k ∝ exp(−[(λ1 − λ2) + (λ1 − λ3) + … + (λ1 − λk)] t) (SALI ∝ exp(−(λ1 − λ2) t)), with the
// exponents of lyapunov_spectrum.hpp. On a regular orbit lying on an N-torus of a nonlinear chain
// (N beads: N degrees of freedom), GALI_k stays of order 1 for 2 ≤ k ≤ N and decays as
// t^(−2(k−N)) for N < k ≤ 2N: the vectors fall into the torus' N-dimensional tangent space and
// its shear (frequencies that depend on the actions) stretches them along it linearly in time. A
// harmonic (linear) chain has no shear: every GALI_k stays bounded.
//
// Rounding floor: rounding in the map keeps feeding every vector components of ~1e-16 relative, so
// on a chaotic orbit GALI_2 and SALI stall at 1e-15 … 1e-14 (measured) and stay there, and an R_jj
// near 1e-14 is no longer the dynamics'; a threshold belongs well above that (the default 1e-8 is
// customary).
//
// Coordinates and norm as the Lyapunov exponents': w = (δu, t_unit δv), t_unit = 1 µs. The values
// of the indices depend on that metric, their rates of decay do not. Both are dimensionless.
//
//   granular::AlignmentIndices a(law, chain, granular::saba2c(), 1e-7, start, {.vectors = 3});
//   a.advance(100000);
//   a.gali();        // {GALI_2, GALI_3} now
//   a.gali_below();  // the first times [s] each fell below config.threshold, if it did
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "granular/dynamics/tangent_map.hpp"

namespace granular {

/// GALI_2 … GALI_k of the k ≥ 2 vectors (entry j is GALI_{j+2}; each vector N beads, non-zero and
/// finite, scaled to unit length in (δu, t_unit δv) first, so their lengths do not matter).
/// Throws InvalidInput naming `vectors` for fewer than 2, more than 2N, unequal sizes, a zero or
/// non-finite vector.
std::vector<double> generalized_alignment_indices(const std::vector<State>& vectors, double time_unit = 1e-6);
/// GALI_k of all k ≥ 2 vectors: the last entry of generalized_alignment_indices.
double generalized_alignment_index(const std::vector<State>& vectors, double time_unit = 1e-6);
/// SALI of two non-zero vectors: min(‖ŵ1 + ŵ2‖, ‖ŵ1 − ŵ2‖) of their unit vectors, in [0, √2].
double smaller_alignment_index(const State& a, const State& b, double time_unit = 1e-6);

struct AlignmentConfig {
  std::size_t vectors = 2;             ///< k deviation vectors, 2 ≤ k ≤ 2N: GALI_2 … GALI_k
  std::size_t renormalize_every = 10;  ///< steps between length renormalizations and threshold checks (≥ 1)
  double threshold = 1e-8;             ///< the indices' level whose first crossing is recorded (> 0)
  double time_unit = 1e-6;             ///< t_unit of the norm [s]
  std::uint64_t seed = 1;              ///< of the random orthonormal starting vectors (LyapunovSpectrum's)
};

/// k deviation vectors carried along one orbit by the tangent map (tangent_map.hpp), never
/// orthonormalized: every config.renormalize_every steps each is scaled back to unit length (which
/// leaves the indices unchanged and keeps the numbers finite), and GALI_2 … GALI_k and SALI are
/// checked against config.threshold.
class AlignmentIndices {
 public:
  /// Starts the orbit at `initial` (a plain run's first state) and k random orthonormal vectors,
  /// those LyapunovSpectrum starts from with the same seed (to rounding: scaled to length 1 once
  /// more), so that its exponents describe the same vectors. Throws InvalidInput naming `vectors`, `renormalize_every`,
  /// `threshold`, `time_unit` or the propagation's parameters.
  AlignmentIndices(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme, double time_step,
                   const State& initial, const AlignmentConfig& config);
  /// The same from given starting vectors (config.vectors and config.seed are ignored; 2 ≤ k ≤ 2N
  /// non-zero vectors, scaled to unit length here).
  AlignmentIndices(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme, double time_step,
                   const State& initial, const std::vector<State>& start, const AlignmentConfig& config);
  AlignmentIndices(const AlignmentIndices&) = delete;  // the map calls back into this object
  AlignmentIndices& operator=(const AlignmentIndices&) = delete;

  /// Advances `steps` steps of τ, renormalizing and checking the threshold every
  /// config.renormalize_every steps of the run (between steps, inside the map: the orbit is a
  /// plain run's advanced by the same calls) and at the end, so that the indices are current.
  void advance(std::size_t steps);

  /// GALI_2 … GALI_k now (entry j is GALI_{j+2}).
  std::vector<double> gali() const { return gali_; }
  /// SALI of the first two vectors now.
  double sali() const { return sali_; }
  /// For each GALI_j (entry j − 2), the first check time [s] at which it was below
  /// config.threshold; none if it has not been. A check that falls inside a merged step boundary
  /// (tangent_map.hpp) sees the vectors up to a step early: the time is good to one step.
  std::vector<std::optional<double>> gali_below() const { return gali_below_; }
  std::optional<double> sali_below() const { return sali_below_; }  ///< the same for SALI
  /// The k unit vectors now (N beads each; δv in 1/s: the norm counts t_unit δv).
  std::vector<State> vectors() const;
  /// The orbit's state and time, the same bit for bit as a plain run's of the scheme.
  State state() const { return tangent_->state(); }
  double time() const { return tangent_->time(); }

 private:
  void start(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme, double time_step,
             const State& initial, const std::vector<State>& vectors);
  void renormalize();  ///< every vector to unit length, then the indices and the threshold checks

  std::unique_ptr<TangentPropagator> tangent_;
  AlignmentConfig config_;
  std::size_t beads_;
  std::vector<double> gali_;
  double sali_ = 0;
  std::vector<std::optional<double>> gali_below_;
  std::optional<double> sali_below_;
  std::uint64_t renormalized_at_ = 0;                  ///< the step of the last renormalization
  std::vector<double> matrix_, tau_, work_, du_, dv_;  ///< the QR's buffers, LAPACK's workspace
};

/// GALI_2 … GALI_k and SALI of k orthonormal starting vectors carried by the tangent map without
/// orthonormalization, read from the R factors of the QR's that do orthonormalize them
/// (LyapunovSpectrum::record_factors): with V(t) = Q(t) P(t), P the product of the R's, the unit
/// vectors are Q p̂_j, so the indices are those of P with its columns scaled to unit length:
/// GALI_j = Π_{i≤j} |p̂_ii|, and SALI = 2 min(sin(θ/2), cos(θ/2)) with θ the angle between p̂_1 and p̂_2.
/// The same numbers as AlignmentIndices from the same start, without a second orbit; kept in P's
/// basis they also keep their digits below its rounding floor of ~1e-15 (until they underflow).
class FactorAlignment {
 public:
  /// P = 1: orthonormal vectors, every GALI 1 and SALI √2. Throws InvalidInput naming `vectors` for k < 2.
  explicit FactorAlignment(std::size_t vectors);
  /// P ← R P, its columns scaled back to unit length (r: k × k, column-major, upper triangular).
  void multiply(std::span<const double> r);
  std::vector<double> gali() const;  ///< GALI_2 … GALI_k now (entry j is GALI_{j+2})
  double sali() const;               ///< SALI of the first two vectors now

 private:
  std::size_t k_;
  std::vector<double> p_, next_;  ///< P̂ (column-major), and the product's scratch
};

/// GALI_2 … GALI_k and SALI of an AlignmentIndices run at the given sample steps (sorted, from 0:
/// step 0 gives the starting vectors' values), and the threshold's first crossings over the run.
struct AlignmentSeries {
  std::vector<double> time;               ///< [s]
  std::vector<std::vector<double>> gali;  ///< gali[s][j] = GALI_{j+2} at time[s]
  std::vector<double> sali;
  std::vector<std::optional<double>> gali_below;  ///< as AlignmentIndices::gali_below at the end
  std::optional<double> sali_below;
};
AlignmentSeries alignment_series(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                                 double time_step, const State& initial, const AlignmentConfig& config,
                                 const std::vector<std::uint64_t>& sample_steps);

}  // namespace granular
