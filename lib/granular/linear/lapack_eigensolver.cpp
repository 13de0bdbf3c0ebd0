#include "granular/linear/lapack_eigensolver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "granular/error.hpp"
#include "granular/linear/lapack.hpp"

namespace granular {

std::string_view to_string(LapackDriver driver) {
  switch (driver) {
    case LapackDriver::stevr: return "stevr";
    case LapackDriver::stemr: return "stemr";
    case LapackDriver::stevd: return "stevd";
    case LapackDriver::steqr: return "steqr";
  }
  return "?";
}

LapackDriver parse_lapack_driver(std::string_view name) {
  for (auto d : {LapackDriver::stevr, LapackDriver::stemr, LapackDriver::stevd, LapackDriver::steqr})
    if (name == to_string(d)) return d;
  throw InvalidInput("LAPACK driver '" + std::string(name) + "': expected stevr, stemr, stevd or steqr");
}

void LapackEigensolver::solve(const SymTridiagonal& t, bool want_vectors, EigenDecomposition& out) {
  const int n = static_cast<int>(t.size());
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
  if (want_vectors) out.vectors.resize(n, n); else out.vectors.resize(0, 0);
  double* z = want_vectors ? out.vectors.data() : nullptr;
  double dummy_z = 0;
  if (!z) z = &dummy_z;
  const double vl = 0, vu = 0, abstol = 0;
  const int il = 0, iu = 0;
  switch (driver) {
    case LapackDriver::stevr: {
      const int lwork = 20 * n, liwork = 10 * n;
      work_.resize(lwork);
      iwork_.resize(liwork);
      isuppz_.resize(2 * n);
      dstevr_(jobz, "A", &n, d_.data(), e_.data(), &vl, &vu, &il, &iu, &abstol, &m, out.values.data(), z, &ldz,
              isuppz_.data(), work_.data(), &lwork, iwork_.data(), &liwork, &info, 1, 1);
      break;
    }
    case LapackDriver::stemr: {
      const int lwork = 18 * n, liwork = 10 * n, nzc = n;
      int tryrac = 1;
      work_.resize(lwork);
      iwork_.resize(liwork);
      isuppz_.resize(2 * n);
      dstemr_(jobz, "A", &n, d_.data(), e_.data(), &vl, &vu, &il, &iu, &m, out.values.data(), z, &ldz, &nzc,
              isuppz_.data(), &tryrac, work_.data(), &lwork, iwork_.data(), &liwork, &info, 1, 1);
      break;
    }
    case LapackDriver::stevd: {
      const int lwork = want_vectors ? 1 + 4 * n + n * n : 1, liwork = want_vectors ? 3 + 5 * n : 1;
      work_.resize(lwork);
      iwork_.resize(liwork);
      dstevd_(jobz, &n, d_.data(), e_.data(), z, &ldz, work_.data(), &lwork, iwork_.data(), &liwork, &info, 1);
      if (info == 0) std::copy(d_.begin(), d_.end(), out.values.data());
      m = n;
      break;
    }
    case LapackDriver::steqr: {
      work_.resize(std::max(1, 2 * n - 2));
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
