#pragma once
// Every mode's ω² and displacement IPR in O(N²) without forming the eigenvector matrix.
//
// Method (one chain, N beads, D the dynamical matrix):
//  1. T = D / max|D_ij| (unit largest entry, as for the LAPACK path); its eigenvalues by the
//     root-free (Pal–Walker–Kahan) QL iteration with Wilkinson shifts, the algorithm of LAPACK's
//     dsterf, O(N²), absolute accuracy ~ε‖T‖ (rational_ql.hpp). Each QL step is a serial chain
//     of divisions, so solve_batch() runs the iterations of up to `group` chains in vector lanes,
//     each lane taking the next chain when its own is done. Results do not depend on the batch:
//     a chain's arithmetic is the same alone or in lanes. More than 30·N QL iterations counts as
//     failure (see 4).
//  2. For each eigenvalue λ that is isolated (see the cluster criterion below), one twisted
//     factorization of T − λI, as in LAPACK's dlar1v (MRRR): the stationary LDLᵀ from the
//     top, the progressive UDUᵀ from the bottom, the twist index r minimizing
//     |γ_r| = |D⁺_r − e_r U_r|, and z with z_r = 1 from the two bidiagonal recurrences.
//     z solves (T − λI) z = γ_r e_r: one step of inverse iteration from the best unit vector,
//     so its angle to the true eigenvector is ≲ (|λ̂ − λ| + O(ε)‖T‖)/gap. Its IPR
//     Σ(z_n m_n^{-1/2})⁴ / (Σ(z_n m_n^{-1/2})²)² is accumulated on the fly; the recurrences
//     stop once |z| < 1e-60. Components keep decaying past that point unless a second
//     localization centre lies beyond it, and a dip to 1e-60 between two centres means a
//     splitting ~1e-120, far inside a cluster, so an isolated mode loses < 1e-100 of its Σz²
//     (truncating at 1e-7 instead is caught by the tests: two-centre modes exist). Sixteen shifts
//     go through the factorizations and the z sweeps together in vector lanes
//     (twisted_lanes.hpp; the recurrences are serial in n, not across shifts; the results are
//     those of the scalar recurrences bit for bit). O(N) per mode, no allocation per solve.
//  3. Clusters. Mode k is *isolated* when its relative gap
//         relgap_k = min(λ_k − λ_{k−1}, λ_{k+1} − λ_k) / max|λ|
//     is at least `cluster_gap` (default 1e-10); maximal runs of consecutive modes whose
//     neighbouring eigenvalues are closer than cluster_gap·max|λ| form a *cluster*. In
//     these chains clusters come from light beads isolated among heavy ones (small ξ):
//     their localized modes have equal local environments, so their ω² agree to anything down
//     to 1e-16 relative and their eigenvectors are not determined by the matrix to working
//     precision — any orthonormal basis of the cluster's invariant subspace is as valid.
//     Twisted vectors at nearly equal shifts may coincide, so each cluster instead gets an
//     orthonormal basis of its invariant subspace by block inverse iteration (cluster_basis.hpp:
//     one factorization, every vector in vector lanes, until the subspace's residual is below
//     `max_residual`·N·ε·max|λ|·√count, then two more solves; LAPACK's dstein, vector by
//     vector, if it does not get there). That basis is rotated to the most localized one
//     (Jacobi sweeps maximizing Σ v⁴, see localize()), its vectors numbered by their Rayleigh
//     quotients (quotients within 1e-13 max|λ|, equal to rounding, by position), and their IPRs
//     used. The rotated basis belongs to the subspace, not to the
//     solver: from dstein's start vectors and from the block iteration's the IPRs agree to
//     2e-8 (400 clusters at N = 1000, ξ = 0.1); other solvers (dstevr, Eigen) may return less
//     localized bases.
//     Outside clusters the result is the IPR of the unique mode.
//  4. Guards: the QL iteration or dstein failing (dstein info ≠ 0), a non-finite value, an IPR
//     outside (0, 1], or a twisted residual |γ_r|/‖z‖ above `max_residual`·N·ε·max|λ| make
//     the whole chain fall back to LapackModeIpr (dstevr with its own fallbacks). `info()`
//     counts how often each path ran.
//
// Accuracy (tests/linear/twisted_ipr_solver_test.cpp). Any backward-stable method — this one,
// dstevr, a dense Eigen solve — gets ω² to ~ε‖D‖ absolute and a mode's IPR to ~1e-15/relgap,
// and that is all the double-precision matrix determines. Against both dstevr and Eigen the
// IPRs agree to 1e-10 (measured ≤ 6e-12) for relgap ≥ 1e-4, to 1e-14/relgap below that down to
// relgap 1e-10, and frequencies to 1e-12 relative where ω² ≥ 1e-3 max ω² (the lowest modes at
// ξ = 0.1 have ω² ~ 1e-7 max ω²; there the two references themselves differ by ~5e-11).
// cluster_gap = 1e-10 is where that bound (1e-4 in the IPR, ~1e-5 in the angle between the
// twisted vectors of neighbouring modes) stops being useful: below it the matrix does not
// single out the modes, and the cluster gets an explicitly orthogonalized basis instead.
// (1e-6 gave the same test results at 25 % more cost per chain: dstein on ~5 modes a chain.)
#include <cstddef>
#include <span>
#include <tuple>
#include <vector>

#include "granular/linear/detail/cluster_basis.hpp"
#include "granular/linear/detail/mode_ipr_solver.hpp"
#include "granular/linear/detail/rational_ql.hpp"
#include "granular/linear/detail/twisted_lanes.hpp"

namespace granular {

struct TwistedIprConfig {
  double cluster_gap = 1e-10;  ///< relative gap below which neighbouring modes form a cluster
  double max_residual = 1e3;   ///< twisted residual limit, in units of N·ε·max|λ|
};

struct TwistedIprInfo {
  std::size_t solves = 0;          ///< chains solved
  std::size_t isolated_modes = 0;  ///< modes done by one twisted factorization
  std::size_t clusters = 0;        ///< clusters, each given an orthonormal basis (cluster_basis.hpp)
  std::size_t cluster_dstein = 0;  ///< of those, clusters cluster_basis left to LAPACK's dstein
  std::size_t cluster_modes = 0;   ///< modes inside those clusters
  std::size_t fallbacks = 0;       ///< chains that fell back to the full LAPACK path
};

class TwistedModeIpr final : public ModeIprSolver {
 public:
  explicit TwistedModeIpr(TwistedIprConfig config = {});
  void solve(const SymTridiagonal& d, const std::vector<double>& inverse_sqrt_mass, std::vector<double>& omega2,
             std::vector<double>& ipr) override;
  void solve_batch(std::span<const ModeIprTask> tasks) override;
  const TwistedIprInfo& info() const { return info_; }
  const TwistedIprConfig& config() const { return config_; }

  /// Batch width of the vectorized twisted factorizations.
  static constexpr std::size_t lanes = detail::twisted_lane_count;
  /// Chains solved together: their QL iterations share the vector lanes of rational_ql_lanes.
  static constexpr std::size_t group = 2 * detail::ql_lane_count;

 private:
  struct Slot {  // one chain's scaled matrix, eigenvalues and scaled m^{-1/2}
    std::vector<double> d, e, e2, lambda, mass;
    std::size_t n = 0;
    double scale = 0;
    bool ok = false;
  };
  void solve_group(std::span<const ModeIprTask> tasks);
  bool load(Slot& slot, const ModeIprTask& task);
  bool solve_modes(const Slot& slot, std::vector<double>& ipr);
  bool twisted_batch(const Slot& slot, const std::size_t* modes, std::size_t count, std::vector<double>& ipr);
  bool cluster(const Slot& slot, std::size_t first, std::size_t count, std::vector<double>& ipr);
  void localize(const Slot& slot, std::size_t count);
  void reserve(std::size_t n);

  TwistedIprConfig config_;
  TwistedIprInfo info_;
  LapackModeIpr fallback_;
  std::size_t capacity_ = 0;
  double residual_limit_ = 0;
  Slot slots_[group];
  detail::QlLaneWork ql_work_;
  detail::TwistedLaneWork lane_work_;  // the batched factorizations
  detail::ClusterWork cluster_work_;
  std::vector<std::size_t> isolated_;
  std::vector<std::tuple<double, std::size_t, std::size_t>> cluster_order_;  // (ρ, centre, vector)
  std::vector<std::size_t> support_;  // localize(): the beads where the cluster's vectors are not negligible
  std::vector<double> gathered_;      // localize(): the vectors on them, then the masses
  std::vector<double> row_largest_;   // localize(): per bead, the largest |z| of the cluster's vectors
  // dstein workspace
  std::vector<double> stein_w_, stein_z_, stein_work_;
  std::vector<int> stein_iblock_, stein_isplit_, stein_iwork_, stein_ifail_;
};

}  // namespace granular
