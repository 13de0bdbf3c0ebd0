#pragma once
// Eigenvalues of a symmetric tridiagonal matrix by index, through inertia (Sturm) counts at many
// shifts in one sweep over the matrix, and their eigenvectors by LAPACK's inverse iteration
// (own, on the dgttrf LU; LAPACK's dstein reorthogonalizes every vector against all within
// 1e-3‖T‖, i.e. all of them for long chains, and was 5× slower). The many-shift sweep is what makes this fast: LAPACK's own bisection (dlaebz) runs
// one shift per sweep, so each O(N) sweep waits on a chain of dependent divisions; here 8–64
// independent shifts share the sweep and fill the vector units. Shifts that share an interval
// are spread over it (multisection) and every count narrows every eigenvalue's bracket.
#include <vector>

#include <Eigen/Core>

#include "granular/linear/sym_tridiagonal.hpp"

namespace granular {

/// Eigenvalues number first … last (1-based, inclusive), ascending, each bracketed to a width of
/// `relative_width` × max|bracket end| (or ~ the pivot floor near 0). Throws InvalidInput on a bad range.
std::vector<double> bisect_eigenvalues(const SymTridiagonal& t, int first, int last, double relative_width);

/// Unit eigenvectors (N × values.size()) for accurate eigenvalues `values` (ascending) by inverse
/// iteration: one O(N) pivoted LU of T − λI (dgttrf), then solves until the residual
/// ‖Tw − ρw‖ ≤ 64 ε ‖T‖ (usually 2), Gram–Schmidt against earlier vectors whose eigenvalues lie
/// within 1e-7 ‖T‖. Each value is replaced by the Rayleigh quotient ρ = wᵀTw. Throws NumericalError.
Eigen::MatrixXd inverse_iteration(const SymTridiagonal& t, std::vector<double>& values);

/// Counts of eigenvalues below each of `shifts` (one sweep over the matrix).
std::vector<long> count_below_many(const SymTridiagonal& t, const std::vector<double>& shifts);

}  // namespace granular
