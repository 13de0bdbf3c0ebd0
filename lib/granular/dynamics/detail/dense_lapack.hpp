#pragma once
// Fortran LAPACK entry points for dense matrices (gfortran calling convention: trailing hidden
// string lengths): Newton's linear solves (periodic_orbit.cpp) and the monodromy matrix's
// eigenvalues (floquet.cpp); the tridiagonal solve of the harmonic-balance seed at F0 = 0
// (breather_branch.cpp).
#include <cstddef>

extern "C" {
void dgesv_(const int* n, const int* nrhs, double* a, const int* lda, int* ipiv, double* b, const int* ldb, int* info);
void dgtsv_(const int* n, const int* nrhs, double* dl, double* d, double* du, double* b, const int* ldb, int* info);
void dgeev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda, double* wr, double* wi,
            double* vl, const int* ldvl, double* vr, const int* ldvr, double* work, const int* lwork, int* info,
            std::size_t, std::size_t);
}

// Householder QR and its Q: the re-orthonormalization of deviation vectors (lyapunov_spectrum.cpp).
extern "C" {
void dgeqrf_(const int* m, const int* n, double* a, const int* lda, double* tau, double* work, const int* lwork,
             int* info);
void dorgqr_(const int* m, const int* n, const int* k, double* a, const int* lda, const double* tau, double* work,
             const int* lwork, int* info);
}

// Covariant Lyapunov vectors (covariant_vectors.cpp): the backward solve C ← R⁻¹ C (BLAS dtrsm)
// and the singular values that give the angles between their subspaces.
extern "C" {
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb, std::size_t, std::size_t,
            std::size_t, std::size_t);
void dgesvd_(const char* jobu, const char* jobvt, const int* m, const int* n, double* a, const int* lda, double* s,
             double* u, const int* ldu, double* vt, const int* ldvt, double* work, const int* lwork, int* info,
             std::size_t, std::size_t);
}
