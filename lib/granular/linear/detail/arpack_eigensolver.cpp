// ARPACK shift-invert (mode 3) on the tridiagonal matrix: OP = (T − σI)⁻¹ by the O(N) LU of
// ShiftInvertOperator; the `count` largest |θ| of OP are the eigenvalues nearest σ.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <mutex>
#include <numeric>
#include <string>

#include "granular/error.hpp"
#include "granular/linear/detail/shift_invert_eigensolvers.hpp"
#include "granular/linear/tridiagonal_operator.hpp"

extern "C" {
void dsaupd_(int* ido, const char* bmat, const int* n, const char* which, const int* nev, const double* tol,
             double* resid, const int* ncv, double* v, const int* ldv, int* iparam, int* ipntr, double* workd,
             double* workl, const int* lworkl, int* info, std::size_t, std::size_t);
void dseupd_(const int* rvec, const char* howmny, int* select, double* d, double* z, const int* ldz,
             const double* sigma, const char* bmat, const int* n, const char* which, const int* nev, const double* tol,
             double* resid, const int* ncv, double* v, const int* ldv, int* iparam, int* ipntr, double* workd,
             double* workl, const int* lworkl, int* info, std::size_t, std::size_t, std::size_t);
}

namespace granular {

namespace {

/// A fixed pseudo-random start vector (splitmix64): ARPACK's own start depends on how many
/// solves ran before in the process, which would make results order-dependent.
void start_vector(double* x, int n) {
  std::uint64_t s = 0x9E3779B97F4A7C15ull;
  for (int i = 0; i < n; ++i) {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    x[i] = static_cast<double>(z >> 11) * 0x1.0p-53 - 0.5;
  }
}

/// ARPACK 3.8 keeps its iteration's state in Fortran SAVE variables (dsaupd, dsaup2, dsaitr):
/// two solves at once in one process corrupt each other's (a threaded crystal IPR map crashed in
/// malloc). One at a time, then; the caller's factorization, before the call, still runs in parallel.
std::mutex arpack_state;

}  // namespace

ShiftInvertResult arpack_shift_invert(int n, double shift, const std::function<void(const double*, double*)>& solve,
                                      const ShiftInvertConfig& config) {
  const int nev = config.count;
  require_nearest_count("ARPACK", static_cast<std::size_t>(n), nev);
  const int ncv = std::min(n, config.subspace > 0 ? std::max(config.subspace, nev + 1) : std::max(2 * nev + 1, 20));

  const int ldv = n, lworkl = ncv * (ncv + 8);
  std::vector<double> resid(n), v(static_cast<std::size_t>(n) * ncv), workd(3 * static_cast<std::size_t>(n)),
      workl(lworkl);
  start_vector(resid.data(), n);
  int iparam[11] = {0}, ipntr[11] = {0};
  iparam[0] = 1;  // exact shifts
  iparam[2] = config.max_restarts;
  iparam[6] = 3;          // shift-invert
  int ido = 0, info = 1;  // info = 1: use resid as the start vector
  const double tol = config.tolerance;
  ShiftInvertResult out;
  const std::lock_guard<std::mutex> one_at_a_time(arpack_state);
  for (;;) {
    dsaupd_(&ido, "I", &n, "LM", &nev, &tol, resid.data(), &ncv, v.data(), &ldv, iparam, ipntr, workd.data(),
            workl.data(), &lworkl, &info, 1, 2);
    if (ido == -1 || ido == 1) {
      solve(&workd[ipntr[0] - 1], &workd[ipntr[1] - 1]);
      ++out.operator_solves;
    } else {
      break;
    }
  }
  if (info == 1)
    throw NumericalError("ARPACK: no convergence after " + std::to_string(iparam[2]) + " restarts (" +
                         std::to_string(iparam[4]) + " of " + std::to_string(nev) + " converged)");
  if (info != 0) throw NumericalError("ARPACK dsaupd: info = " + std::to_string(info));
  out.restarts = iparam[2];

  const int rvec = 1;
  std::vector<int> select(ncv);
  std::vector<double> d(nev);
  Eigen::MatrixXd z(n, nev);
  dseupd_(&rvec, "A", select.data(), d.data(), z.data(), &ldv, &shift, "I", &n, "LM", &nev, &tol, resid.data(), &ncv,
          v.data(), &ldv, iparam, ipntr, workd.data(), workl.data(), &lworkl, &info, 1, 1, 2);
  if (info != 0) throw NumericalError("ARPACK dseupd: info = " + std::to_string(info));
  const int converged = iparam[4];
  if (converged < nev)
    throw NumericalError("ARPACK: " + std::to_string(converged) + " of " + std::to_string(nev) + " converged");

  std::vector<int> order(nev);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return d[a] < d[b]; });
  out.values.resize(nev);
  out.vectors.resize(n, nev);
  for (int i = 0; i < nev; ++i) {
    out.values[i] = d[order[i]];
    out.vectors.col(i) = z.col(order[i]);
  }
  if (!out.vectors.allFinite()) throw NumericalError("ARPACK returned non-finite eigenvectors");
  return out;
}

ShiftInvertResult arpack_nearest(const SymTridiagonal& t, double sigma, const ShiftInvertConfig& config) {
  require_nearest_count("ARPACK", t.size(), config.count);
  ShiftInvertOperator op;
  op.factorize(t, sigma);
  return arpack_shift_invert(
      static_cast<int>(t.size()), op.shift(), [&](const double* x, double* y) { op.apply(x, y); }, config);
}

}  // namespace granular
