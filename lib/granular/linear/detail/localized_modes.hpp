#pragma once
// Eigenvectors of localized modes on a window of the chain (the `bisect` method, long chains).
// In a long disordered chain a mode decays exponentially away from its centre, so its eigenvector
// is, to machine precision, that of a few thousand rows: solving there costs O(window) instead of
// O(N) per sweep, and 2 N × lanes doubles of workspace (128 MB at N = 1e6, 8 lanes) shrink to the
// window's. Nothing is assumed: a window's vector, extended by zeros, is accepted only if its
// residual in the whole chain, ‖T w − ρ w‖ (the rows just outside the window included), meets the
// same target as a whole-chain solve and ρ stays in the eigenvalue's isolating bracket; else the
// window grows, and a mode that no window holds is left to the whole-chain solve (extended modes).
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "granular/linear/sym_tridiagonal.hpp"

namespace granular {

/// Where each isolated eigenvalue's mode sits: for bracket j = [lo_j, hi_j] (brackets, 2 m
/// entries) holding exactly one eigenvalue, the last row i at which the leading block T[0..i]
/// gains an eigenvalue in [lo_j, hi_j) for good — a few localization lengths right of the mode's
/// centre. One many-shift sweep over the matrix (the inertia counts of the bracket ends, row by row).
std::vector<std::size_t> mode_anchors(const SymTridiagonal& t, const std::vector<double>& brackets);

struct LocalizedModes {
  std::vector<double> values;    ///< refined eigenvalues (Rayleigh quotients); input value where not solved
  std::vector<double> ipr;       ///< displacement IPR (where solved)
  std::vector<double> residual;  ///< ‖T w − ρ w‖ in the whole chain, unit w (where solved)
  std::vector<bool> solved;      ///< false: no window held the mode (or it is clustered): solve it in the whole chain
};

/// For eigenvalues `values` (ascending) isolated in `brackets` (bisect_eigenvalues), the modes
/// whose windows hold them: values, IPRs of v = w ⊙ inverse_sqrt_mass, residuals and, when
/// `vectors` is not null (N × m), their unit vectors in its columns (zero outside the window).
/// Modes whose brackets are within 1e-10 ‖T‖ of a neighbour's are left unsolved (clusters need
/// the whole-chain solve's orthogonalization), and so is every mode when N < 4 × 2048.
LocalizedModes solve_localized_modes(const SymTridiagonal& t, const std::vector<double>& values,
                                     const std::vector<double>& brackets, const std::vector<double>& inverse_sqrt_mass,
                                     Eigen::MatrixXd* vectors);

}  // namespace granular
