#include "granular/linear/detail/lapack_eigensolver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "granular/detail/enum_names.hpp"
#include "granular/error.hpp"
#include "granular/linear/detail/lapack.hpp"
#include "granular/linear/tridiagonal_operator.hpp"

namespace granular {

constexpr auto driver_names = detail::enum_names<LapackDriver>("driver", {{LapackDriver::stevr, "stevr"},
                                                                          {LapackDriver::stemr, "stemr"},
                                                                          {LapackDriver::stevd, "stevd"},
                                                                          {LapackDriver::steqr, "steqr"}});

std::string_view to_string(LapackDriver driver) { return driver_names.name_of(driver); }

LapackDriver parse_lapack_driver(std::string_view name) { return driver_names.parse(name); }

using detail::lapack_int;

void LapackEigensolver::solve(const SymTridiagonal& t, bool want_vectors, EigenDecomposition& out) {
  const int n = lapack_int(static_cast<std::int64_t>(t.size()), "the matrix");
  if (n < 1) throw InvalidInput("eigen-solve of an empty matrix");
  const double scale = t.max_abs();
  if (!std::isfinite(scale) || !t.all_finite()) throw NumericalError("dynamical matrix has a non-finite entry");
  const double inv = scale > 0 ? 1.0 / scale : 1.0;

  std::vector<LapackDriver> order{preferred_};
  for (auto d : {LapackDriver::stevr, LapackDriver::stevd, LapackDriver::steqr})
    if (d != preferred_) order.push_back(d);

  out.fallbacks = 0;
  for (LapackDriver driver : order) {
    d_.resize(n);
    e_.assign(std::max(n, 1), 0.0);  // stevr/stemr want n entries in e
    for (int i = 0; i < n; ++i) d_[i] = t.diagonal[i] * inv;
    for (int i = 0; i + 1 < n; ++i) e_[i] = t.off_diagonal[i] * inv;
    if (run(driver, want_vectors, n, out) == 0) {
      out.values *= scale > 0 ? scale : 1.0;
      out.driver = driver;
      return;
    }
    ++out.fallbacks;
  }
  throw NumericalError("every LAPACK tridiagonal eigen-solver failed (n = " + std::to_string(n) + ")");
}

int LapackEigensolver::run(LapackDriver driver, bool want_vectors, int n, EigenDecomposition& out) {
  const char* jobz = want_vectors ? "V" : "N";
  const int ldz = std::max(n, 1);
  int info = 0, m = 0;
  out.values.resize(n);
  if (want_vectors) out.vectors.resize(n, n);
  else out.vectors.resize(0, 0);
  double* z = want_vectors ? out.vectors.data() : nullptr;
  double dummy_z = 0;
  if (!z) z = &dummy_z;
  const double vl = 0, vu = 0, abstol = 0;
  const int il = 0, iu = 0;
  switch (driver) {
    case LapackDriver::stevr: {
      const int lwork = lapack_int(20 * std::int64_t{n}, "dstevr's workspace"),
                liwork = lapack_int(10 * std::int64_t{n}, "dstevr's integer workspace");
      work_.resize(lwork);
      iwork_.resize(liwork);
      isuppz_.resize(2 * static_cast<std::size_t>(n));
      dstevr_(jobz, "A", &n, d_.data(), e_.data(), &vl, &vu, &il, &iu, &abstol, &m, out.values.data(), z, &ldz,
              isuppz_.data(), work_.data(), &lwork, iwork_.data(), &liwork, &info, 1, 1);
      break;
    }
    case LapackDriver::stemr: {
      const int lwork = lapack_int(18 * std::int64_t{n}, "dstemr's workspace"),
                liwork = lapack_int(10 * std::int64_t{n}, "dstemr's integer workspace"), nzc = n;
      int tryrac = 1;
      work_.resize(lwork);
      iwork_.resize(liwork);
      isuppz_.resize(2 * static_cast<std::size_t>(n));
      dstemr_(jobz, "A", &n, d_.data(), e_.data(), &vl, &vu, &il, &iu, &m, out.values.data(), z, &ldz, &nzc,
              isuppz_.data(), &tryrac, work_.data(), &lwork, iwork_.data(), &liwork, &info, 1, 1);
      break;
    }
    case LapackDriver::stevd: {
      // Ask dstevd for its workspace (lwork = -1) instead of spelling out 1 + 4n + n², which
      // overflows an int above n = 46338; an answer past the LP64 limit is refused, not wrapped.
      // A fallback reaches it from any preferred driver: past the limit it fails as a driver does.
      if (want_vectors && detail::stevd_workspace_overflows(n)) {
        info = -1003;
        break;
      }
      int lwork = -1, liwork = -1;
      work_.resize(std::max<std::size_t>(work_.size(), 1));
      iwork_.resize(std::max<std::size_t>(iwork_.size(), 1));
      dstevd_(jobz, &n, d_.data(), e_.data(), z, &ldz, work_.data(), &lwork, iwork_.data(), &liwork, &info, 1);
      if (info != 0) break;
      lwork = lapack_int(static_cast<std::int64_t>(std::ceil(work_[0])), "dstevd's workspace");
      liwork = std::max(iwork_[0], 1);
      work_.resize(static_cast<std::size_t>(std::max(lwork, 1)));
      iwork_.resize(static_cast<std::size_t>(liwork));
      dstevd_(jobz, &n, d_.data(), e_.data(), z, &ldz, work_.data(), &lwork, iwork_.data(), &liwork, &info, 1);
      if (info == 0) std::copy(d_.begin(), d_.end(), out.values.data());
      m = n;
      break;
    }
    case LapackDriver::steqr: {
      work_.resize(static_cast<std::size_t>(std::max<std::int64_t>(1, 2 * std::int64_t{n} - 2)));
      dsteqr_(want_vectors ? "I" : "N", &n, d_.data(), e_.data(), z, &ldz, work_.data(), &info, 1);
      if (info == 0) std::copy(d_.begin(), d_.end(), out.values.data());
      m = n;
      break;
    }
  }
  if (info == 0 && m != n) info = -1000;
  if (info == 0 && !out.values.allFinite()) info = -1001;
  if (info == 0 && want_vectors && !out.vectors.allFinite()) info = -1002;
  return info;
}

}  // namespace granular

namespace granular {

void LapackEigensolver::solve_indices(const SymTridiagonal& t, int first, int last, bool want_vectors,
                                      EigenDecomposition& out) {
  const int n = static_cast<int>(t.size());
  if (n < 1) throw InvalidInput("eigen-solve of an empty matrix");
  if (first < 1 || last < first || last > n)
    throw InvalidInput("eigenvalue index range " + std::to_string(first) + ".." + std::to_string(last) +
                       ": must satisfy 1 <= first <= last <= N = " + std::to_string(n));
  const double scale = t.max_abs();
  if (!std::isfinite(scale)) throw NumericalError("dynamical matrix has a non-finite entry");
  const double inv = scale > 0 ? 1.0 / scale : 1.0;

  // dstemr first: dstevr runs MRRR only for the whole spectrum and answers a subset with
  // dstebz + dstein (bisection + inverse iteration), 20–40× slower at N = 1e6.
  std::vector<LapackDriver> order{LapackDriver::stemr};
  if (preferred_ == LapackDriver::stevr) order.push_back(LapackDriver::stevr);
  out.fallbacks = 0;
  auto load = [&] {
    d_.resize(n);
    e_.assign(std::max(n, 1), 0.0);
    for (int i = 0; i < n; ++i) d_[i] = t.diagonal[i] * inv;
    for (int i = 0; i + 1 < n; ++i) e_[i] = t.off_diagonal[i] * inv;
  };
  for (LapackDriver driver : order) {
    if (driver != LapackDriver::stevr && driver != LapackDriver::stemr) continue;  // no range variant
    load();
    if (run_indices(driver, want_vectors, n, first, last, out) == 0) {
      out.values *= scale > 0 ? scale : 1.0;
      out.driver = driver;
      return;
    }
    ++out.fallbacks;
  }
  load();
  if (run_bisection(want_vectors, n, first, last, out) == 0) {
    out.values *= scale > 0 ? scale : 1.0;
    out.driver = LapackDriver::steqr;  // not MRRR: bisection + inverse iteration
    return;
  }
  throw NumericalError("every LAPACK range eigen-solver failed (n = " + std::to_string(n) + ", modes " +
                       std::to_string(first) + ".." + std::to_string(last) + ")");
}

void LapackEigensolver::solve_window(const SymTridiagonal& t, double lo, double hi, bool want_vectors,
                                     EigenDecomposition& out) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || hi < lo)
    throw InvalidInput("eigenvalue window: need finite lo <= hi");
  const TridiagonalOperator op(t);
  // λ ≥ lo ⇔ not below lo; λ ≤ hi ⇔ below the next double above hi.
  const auto below_lo = op.count_below(lo);
  const auto up_to_hi = op.count_below(std::nextafter(hi, std::numeric_limits<double>::infinity()));
  out.fallbacks = 0;
  if (up_to_hi <= below_lo) {
    out.values.resize(0);
    out.vectors.resize(want_vectors ? static_cast<Eigen::Index>(t.size()) : 0, 0);
    return;
  }
  solve_indices(t, static_cast<int>(below_lo) + 1, static_cast<int>(up_to_hi), want_vectors, out);
}

int LapackEigensolver::run_indices(LapackDriver driver, bool want_vectors, int n, int first, int last,
                                   EigenDecomposition& out) {
  const char* jobz = want_vectors ? "V" : "N";
  const int wanted = last - first + 1;
  const int ldz = std::max(n, 1);
  int info = 0, m = 0;
  out.values.resize(n);  // LAPACK may write up to N values into w
  if (want_vectors) out.vectors.resize(n, wanted);
  else out.vectors.resize(0, 0);
  double dummy_z = 0;
  double* z = want_vectors ? out.vectors.data() : &dummy_z;
  const double vl = 0, vu = 0, abstol = 0;
  isuppz_.resize(2 * static_cast<std::size_t>(std::max(wanted, 1)));
  if (driver == LapackDriver::stevr) {
    const int lwork = lapack_int(20 * std::int64_t{n}, "dstevr's workspace"),
              liwork = lapack_int(10 * std::int64_t{n}, "dstevr's integer workspace");
    work_.resize(lwork);
    iwork_.resize(liwork);
    dstevr_(jobz, "I", &n, d_.data(), e_.data(), &vl, &vu, &first, &last, &abstol, &m, out.values.data(), z, &ldz,
            isuppz_.data(), work_.data(), &lwork, iwork_.data(), &liwork, &info, 1, 1);
  } else {
    const int lwork = lapack_int(18 * std::int64_t{n}, "dstemr's workspace"),
              liwork = lapack_int(10 * std::int64_t{n}, "dstemr's integer workspace"), nzc = wanted;
    int tryrac = 1;
    work_.resize(lwork);
    iwork_.resize(liwork);
    dstemr_(jobz, "I", &n, d_.data(), e_.data(), &vl, &vu, &first, &last, &m, out.values.data(), z, &ldz, &nzc,
            isuppz_.data(), &tryrac, work_.data(), &lwork, iwork_.data(), &liwork, &info, 1, 1);
  }
  if (info == 0 && m != wanted) info = -1000;
  out.values.conservativeResize(wanted);
  if (info == 0 && !out.values.allFinite()) info = -1001;
  if (info == 0 && want_vectors && !out.vectors.allFinite()) info = -1002;
  return info;
}

int LapackEigensolver::run_bisection(bool want_vectors, int n, int first, int last, EigenDecomposition& out) {
  const int wanted = last - first + 1;
  const double vl = 0, vu = 0, abstol = 0;
  int m = 0, nsplit = 0, info = 0;
  std::vector<double> w(n);
  std::vector<int> iblock(n), isplit(n);
  work_.resize(5 * static_cast<std::size_t>(n));
  iwork_.resize(3 * static_cast<std::size_t>(n));
  // 'B': grouped by split block, as dstein needs.
  dstebz_("I", "B", &n, &vl, &vu, &first, &last, &abstol, d_.data(), e_.data(), &m, &nsplit, w.data(), iblock.data(),
          isplit.data(), work_.data(), iwork_.data(), &info, 1, 1);
  if (info != 0 || m != wanted) return info != 0 ? info : -1000;
  out.values.resize(wanted);
  Eigen::MatrixXd z;
  if (want_vectors) {
    z.resize(n, wanted);
    std::vector<int> ifail(wanted);
    const int ldz = n;
    dstein_(&n, d_.data(), e_.data(), &m, w.data(), iblock.data(), isplit.data(), z.data(), &ldz, work_.data(),
            iwork_.data(), ifail.data(), &info);
    if (info != 0) return info;
  }
  std::vector<int> order(wanted);
  for (int i = 0; i < wanted; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return w[a] < w[b]; });
  if (want_vectors) out.vectors.resize(n, wanted);
  else out.vectors.resize(0, 0);
  for (int i = 0; i < wanted; ++i) {
    out.values[i] = w[order[i]];
    if (want_vectors) out.vectors.col(i) = z.col(order[i]);
  }
  if (!out.values.allFinite() || (want_vectors && !out.vectors.allFinite())) return -1001;
  return 0;
}

}  // namespace granular
