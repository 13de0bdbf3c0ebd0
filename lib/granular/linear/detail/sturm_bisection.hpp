#pragma once
// The `bisect` partial-spectrum method: eigenvalues of a symmetric tridiagonal matrix by index,
// from inertia (Sturm) counts at many shifts per sweep over the matrix, and their eigenvectors
// by inverse iteration. LAPACK's own bisection (dlaebz, inside dstemr/dstebz) runs one shift per
// O(N) sweep, a chain of dependent divisions; here up to 32 independent shifts share a sweep and
// fill the vector units, shifts sharing a bracket are spread over it (multisection), and every
// count narrows every bracket. Eigenvectors come from Rayleigh-quotient inverse iteration on
// several vectors at once (lane_inverse_iteration), or one by one on the pivoted LU
// (inverse_iteration; LAPACK's dstein was 5× slower: it reorthogonalizes every vector against
// all others within 1e-3‖T‖, i.e. all of them in a long chain).
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "granular/linear/sym_tridiagonal.hpp"

namespace granular {

/// Eigenvalues number first … last (1-based, inclusive), ascending, each bracketed to a width of
/// `relative_width` × max|bracket end| (or ~ the pivot floor near 0) — or only to `isolated_width`
/// (relative) once the bracket holds that eigenvalue alone and the neighbouring lanes' brackets are
/// at least twice its width away, which is all a Rayleigh-quotient refinement needs
/// (lane_inverse_iteration: its shift stays in the bracket, ≥ 5× nearer this eigenvalue than another). Throws
/// InvalidInput on a bad range. `brackets`, if given, receives each eigenvalue's final bracket [lo, hi] (2 m entries).
/// `centre` (finite): where the eigenvalues are expected (e.g. the shift of a nearest selection);
/// the first sweep then probes around it instead of evenly over the spectrum. Results do not
/// depend on it beyond the brackets' last bits.
/// `nearest` = K > 0 (with a finite centre): only the K eigenvalues nearest the centre in √λ (in
/// frequency) and their neighbours by index are wanted. A lane stops as soon as K others are
/// certainly nearer than all of its bracket, and so does every lane not beside one that may still
/// be among the K nearest; its value is then its bracket's midpoint, never nearer than the K.
std::vector<double> bisect_eigenvalues(const SymTridiagonal& t, int first, int last, double relative_width,
                                       double isolated_width = 0, std::vector<double>* brackets = nullptr,
                                       double centre = std::numeric_limits<double>::quiet_NaN(),
                                       std::size_t nearest = 0);

/// Unit eigenvectors (N × values.size()) for accurate eigenvalues `values` (ascending) by inverse
/// iteration: one O(N) pivoted LU of T − λI (dgttrf), then solves until the residual
/// ‖Tw − ρw‖ ≤ 64 ε ‖T‖ (usually 2), Gram–Schmidt against earlier vectors whose eigenvalues lie
/// within 1e-10 ‖T‖ (closer than full-precision bisection separates). Each value is replaced by
/// the Rayleigh quotient ρ = wᵀTw. Throws NumericalError.
Eigen::MatrixXd inverse_iteration(const SymTridiagonal& t, std::vector<double>& values);

/// The same, for all vectors at once: each sweep factorizes T − μ_j I = L D Lᵀ (no pivoting; a
/// pivot below ε‖T‖ is raised to ε‖T‖, as LAPACK's dlagtf does for inverse iteration) and solves
/// for every lane j together, so the divisions of different lanes overlap in the vector units.
/// μ_j starts at `values` and moves to the Rayleigh quotient while that keeps it inside the gap
/// (Rayleigh-quotient iteration, cubic), until every residual ‖Tw − ρw‖ ≤ 64 ε ‖T‖. Lanes whose
/// shifts (or brackets) are within 1e-10 ‖T‖ are Gram–Schmidt orthogonalized. At most 64 lanes; throws
/// NumericalError when a lane does not converge in 6 sweeps (callers then bisect to full
/// precision and use inverse_iteration). Memory: 2 N × group doubles besides the result; lanes
/// are solved in groups that never split a cluster (8 lanes fill one AVX-512 register).
/// With `brackets` (from bisect_eigenvalues) a shift only moves, and a lane only counts as
/// converged, inside its own bracket: a lane cannot drift to a neighbour's eigenvalue.
/// Inverse iteration's targets in units of ‖T‖ (max_abs): a unit vector is converged at a
/// residual ≤ kResidualTarget (64 ε), and eigenvalues (or brackets) closer than kClusterGap are
/// one cluster. Shared by every inverse iteration on a tridiagonal (whole chain and windows).
inline constexpr double kResidualTarget = 64 * std::numeric_limits<double>::epsilon(), kClusterGap = 1e-10;

struct LaneOptions {
  std::size_t group = 8;     ///< lanes solved together (memory 2 N × group doubles); 0 = all at once
  bool keep_vectors = true;  ///< false: return an N × 0 matrix (IPR and residuals still computed)
  const std::vector<double>* inverse_sqrt_mass = nullptr;  ///< with `ipr`: IPRs of v = w ⊙ this
  std::vector<double>* ipr = nullptr;                      ///< if set: the displacement IPR of each lane
  std::vector<double>* residual = nullptr;                 ///< if set: ‖Tw − ρw‖ of each unit vector
};
Eigen::MatrixXd lane_inverse_iteration(const SymTridiagonal& t, std::vector<double>& values,
                                       const std::vector<double>* brackets = nullptr, const LaneOptions& options = {});

/// Counts of eigenvalues below each of `shifts` (one sweep over the matrix).
std::vector<long> count_below_many(const SymTridiagonal& t, const std::vector<double>& shifts);

}  // namespace granular
