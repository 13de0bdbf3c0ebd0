#pragma once
// Fortran LAPACK entry points used by the linear module (reference LAPACK or any BLAS/LAPACK
// with the gfortran calling convention: trailing hidden string lengths).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "granular/error.hpp"

namespace granular::detail {

/// A LAPACK size computed in 64 bits, or read back from a workspace query, as the LP64
/// interface's int. Refused (InvalidInput naming N) when larger than an int, and when negative:
/// that is a size LAPACK computed in its own 32-bit arithmetic and wrapped (dstevd's n² + 4n + 1
/// above n = 46338), which once became a one-entry workspace.
inline int lapack_int(std::int64_t size, const char* what) {
  if (size > std::numeric_limits<int>::max())
    throw InvalidInput("N", ": " + std::string(what) + " needs " + std::to_string(size) +
                                " entries, more than LAPACK's 32-bit sizes allow");
  if (size < 0)
    throw InvalidInput("N", ": " + std::string(what) + " came back as " + std::to_string(size) +
                                " entries, a size wrapped past LAPACK's 32-bit limit");
  return static_cast<int>(size);
}

/// dstevd's workspace with eigenvectors, n² + 4n + 1 doubles, past an int: from n = 46339 on.
inline bool stevd_workspace_overflows(std::int64_t n) { return n * n + 4 * n + 1 > std::numeric_limits<int>::max(); }

}  // namespace granular::detail

extern "C" {
void dstevr_(const char* jobz, const char* range, const int* n, double* d, double* e, const double* vl,
             const double* vu, const int* il, const int* iu, const double* abstol, int* m, double* w, double* z,
             const int* ldz, int* isuppz, double* work, const int* lwork, int* iwork, const int* liwork, int* info,
             std::size_t, std::size_t);
void dstemr_(const char* jobz, const char* range, const int* n, double* d, double* e, const double* vl,
             const double* vu, const int* il, const int* iu, int* m, double* w, double* z, const int* ldz,
             const int* nzc, int* isuppz, int* tryrac, double* work, const int* lwork, int* iwork, const int* liwork,
             int* info, std::size_t, std::size_t);
void dstevd_(const char* jobz, const int* n, double* d, double* e, double* z, const int* ldz, double* work,
             const int* lwork, int* iwork, const int* liwork, int* info, std::size_t);
void dsteqr_(const char* compz, const int* n, double* d, double* e, double* z, const int* ldz, double* work, int* info,
             std::size_t);
void dsterf_(const int* n, double* d, double* e, int* info);
void dstein_(const int* n, const double* d, const double* e, const int* m, const double* w, const int* iblock,
             const int* isplit, double* z, const int* ldz, double* work, int* iwork, int* ifail, int* info);
}

// Dense symmetric eigenproblems (every mode of a small 2D crystal): divide and conquer.
extern "C" {
void dsyevd_(const char* jobz, const char* uplo, const int* n, double* a, const int* lda, double* w, double* work,
             const int* lwork, int* iwork, const int* liwork, int* info, std::size_t, std::size_t);
}

// Partial spectra: general tridiagonal LU (shift-invert solves) and bisection + inverse iteration.
extern "C" {
void dgttrf_(const int* n, double* dl, double* d, double* du, double* du2, int* ipiv, int* info);
void dgttrs_(const char* trans, const int* n, const int* nrhs, const double* dl, const double* d, const double* du,
             const double* du2, const int* ipiv, double* b, const int* ldb, int* info, std::size_t);
void dstebz_(const char* range, const char* order, const int* n, const double* vl, const double* vu, const int* il,
             const int* iu, const double* abstol, const double* d, const double* e, int* m, int* nsplit, double* w,
             int* iblock, int* isplit, double* work, int* iwork, int* info, std::size_t, std::size_t);
}
