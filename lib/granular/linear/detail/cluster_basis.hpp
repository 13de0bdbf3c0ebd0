#pragma once
// An orthonormal basis of the invariant subspace of a tight cluster of eigenvalues of a symmetric
// tridiagonal T, for TwistedModeIpr (twisted_ipr_solver.hpp, step 3): its eigenvectors are not
// determined one by one to working precision, only their span is.
//
// Method: block inverse iteration with one shift. T − σI, σ the cluster's midpoint, is factored
// once by LAPACK's dgttrf (LU with partial pivoting; an exactly zero pivot, σ on an eigenvalue,
// becomes ε‖T‖ as in dlagtf); then X ← (T − σI)⁻¹ X and an orthonormalization (modified
// Gram–Schmidt, twice) repeat from deterministic pseudo-random starts until the subspace's
// residual ‖T X − X (Xᵀ T X)‖_F ≤ tolerance, then two more solves: the residual bounds the angle
// to the subspace only by residual / gap. Each solve shrinks the rest of the spectrum's components
// by (half the cluster's width) / (its distance from σ); the solver's clusters can sit as close as
// one width to their neighbours, so up to 40 solves are allowed (3–4 sufficed on 400 clusters at
// N = 1000, ξ = 0.1). The solves run every right-hand side of a row in vector lanes (X is stored
// by rows), where LAPACK's dstein did one vector at a time with a factorization and a random
// start each (docs/performance.md, "Clusters by block inverse iteration").
#include <cstddef>
#include <vector>

namespace granular::detail {

/// Scratch of cluster_basis, kept between calls.
struct ClusterWork {
  std::vector<double> dl, d, du, du2, x, tx;
  std::vector<int> pivots;
};

/// The `count` columns of z (n × count, column-major) become an orthonormal basis of the invariant
/// subspace of T (diagonal d, off-diagonal e; n ≥ 2) for its eigenvalues lambda[0 … count),
/// consecutive in the spectrum. `tolerance` bounds ‖T X − X (Xᵀ T X)‖_F. False when the iteration
/// did not reach it (the caller falls back).
bool cluster_basis(const double* d, const double* e, std::size_t n, const double* lambda, std::size_t count,
                   double tolerance, double* z, ClusterWork& work);

}  // namespace granular::detail
