// The largest-modulus Floquet multipliers without the monodromy matrix (floquet.hpp): ARPACK's
// nonsymmetric implicitly restarted Arnoldi (dnaupd/dneupd, regular mode) on v ↦ M v, one tangent
// integration of the period per product. Cost: (Arnoldi products) × one period, against 2N periods
// and an O(N³) dgeev for the dense matrix.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "granular/detail/euclidean_norm.hpp"
#include "granular/error.hpp"
#include "granular/orbits/detail/floquet_verdict.hpp"
#include "granular/orbits/floquet.hpp"

extern "C" {
void dnaupd_(int* ido, const char* bmat, const int* n, const char* which, const int* nev, const double* tol,
             double* resid, const int* ncv, double* v, const int* ldv, int* iparam, int* ipntr, double* workd,
             double* workl, const int* lworkl, int* info, std::size_t, std::size_t);
void dneupd_(const int* rvec, const char* howmny, int* select, double* dr, double* di, double* z, const int* ldz,
             const double* sigmar, const double* sigmai, double* workev, const char* bmat, const int* n,
             const char* which, const int* nev, const double* tol, double* resid, const int* ncv, double* v,
             const int* ldv, int* iparam, int* ipntr, double* workd, double* workl, const int* lworkl, int* info,
             std::size_t, std::size_t, std::size_t);
}

namespace granular {
namespace {

// A fixed pseudo-random start vector (splitmix64), as for the symmetric ARPACK solver: ARPACK's own
// start depends on what ran before in the process, which would make results order-dependent.
void floquet_arpack_start(std::vector<double>& x) {
  std::uint64_t s = 0x2545F4914F6CDD1Dull;
  for (double& xi : x) {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    xi = static_cast<double>(z >> 11) * 0x1.0p-53 - 0.5;
  }
}

void check_floquet_arpack_config(const FloquetConfig& c, std::size_t beads) {
  const long m = 2 * static_cast<long>(beads);
  if (c.multipliers < 1 || c.multipliers > m - 3)
    throw InvalidInput("multipliers", " " + std::to_string(c.multipliers) +
                                          ": ARPACK needs 1 <= multipliers <= 2N - 3 (" + std::to_string(m - 3) +
                                          "); the dense method gives all 2N");
  if (c.subspace != 0 && (c.subspace < c.multipliers + 2 || c.subspace > m))
    throw InvalidInput("subspace", " " + std::to_string(c.subspace) + ": must be 0 or multipliers + 2 … 2N");
  if (!(c.arpack_tolerance >= 0) || !std::isfinite(c.arpack_tolerance))
    throw InvalidInput("arpack_tolerance", ": must be finite and >= 0");
  if (c.max_restarts < 1) throw InvalidInput("max_restarts", ": must be >= 1");
  if (!(c.tolerance >= 0) || !std::isfinite(c.tolerance)) throw InvalidInput("tolerance", ": must be finite and >= 0");
  if (!(c.unit_pair_window >= 0) || !std::isfinite(c.unit_pair_window))
    throw InvalidInput("unit_pair_window", ": must be finite and >= 0");
  if (!(c.ritz_residual_limit > 0) || !std::isfinite(c.ritz_residual_limit))
    throw InvalidInput("ritz_residual_limit", ": must be finite and > 0");
}

}  // namespace

int floquet_subspace(const FloquetConfig& config, std::size_t beads) {
  const int n = static_cast<int>(2 * beads);
  return config.subspace > 0 ? config.subspace : std::min(n, std::max(2 * config.multipliers + 1, 40));
}

FloquetSpectrum largest_floquet_multipliers(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit,
                                            const FloquetConfig& config) {
  FloquetSpectrum s = try_largest_floquet_multipliers(law, chain, orbit, config);
  if (s.multipliers.empty())
    throw NumericalError("floquet: ARPACK converged no multiplier in " + std::to_string(config.max_restarts) +
                         " restarts");
  return s;
}

FloquetSpectrum try_largest_floquet_multipliers(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit,
                                                const FloquetConfig& config) {
  check_floquet_arpack_config(config, chain.size());
  const int n = static_cast<int>(2 * chain.size());
  const int nev = config.multipliers;
  const int ncv = floquet_subspace(config, chain.size());
  const int ldv = n, lworkl = 3 * ncv * ncv + 6 * ncv;
  std::vector<double> resid(static_cast<std::size_t>(n)), v(static_cast<std::size_t>(n) * ncv),
      workd(3 * static_cast<std::size_t>(n)), workl(static_cast<std::size_t>(lworkl)), w(static_cast<std::size_t>(n));
  floquet_arpack_start(resid);
  int iparam[11] = {0}, ipntr[14] = {0};
  iparam[0] = 1;  // exact shifts
  iparam[2] = config.max_restarts;
  iparam[6] = 1;          // regular mode: OP = M
  int ido = 0, info = 1;  // info = 1: resid is the start vector
  const double tol = config.arpack_tolerance;
  FloquetSpectrum s;
  s.method = "arpack";
  for (;;) {
    dnaupd_(&ido, "I", &n, "LM", &nev, &tol, resid.data(), &ncv, v.data(), &ldv, iparam, ipntr, workd.data(),
            workl.data(), &lworkl, &info, 1, 2);
    if (ido != -1 && ido != 1) break;
    const double* x = &workd[static_cast<std::size_t>(ipntr[0] - 1)];
    std::copy(x, x + n, w.begin());
    const auto y = apply_monodromy(law, chain, orbit, w);
    std::copy(y.begin(), y.end(), &workd[static_cast<std::size_t>(ipntr[1] - 1)]);
    ++s.operator_applications;
  }
  // info = 1: the restarts ran out. On a stable orbit every |μ| = 1 and Arnoldi has no modulus gap
  // to converge on; the multipliers that did converge are kept (complete = false, docs/breathers.md).
  if (info != 0 && info != 1) throw NumericalError("floquet: ARPACK dnaupd failed (info " + std::to_string(info) + ")");
  s.complete = info == 0;
  s.restarts = iparam[2];
  if (info == 1 && iparam[4] < 1) {  // none converged
    s.instability = "unknown";
    return s;
  }
  // dnaupd's Ritz values of its last Hessenberg matrix and their error estimates |β e_k^T y|
  // (ARPACK's own convergence test), read before dneupd reuses the workspace.
  const auto at = [&](int pointer) { return workl.begin() + (pointer - 1); };
  const std::vector<double> ritz_re(at(ipntr[5]), at(ipntr[5]) + ncv), ritz_im(at(ipntr[6]), at(ipntr[6]) + ncv),
      bounds(at(ipntr[7]), at(ipntr[7]) + ncv);

  const int rvec = 1;  // the Ritz vectors, for the measured residuals
  std::vector<int> select(static_cast<std::size_t>(ncv));
  std::vector<double> dr(static_cast<std::size_t>(nev) + 1), di(dr.size()), workev(3 * static_cast<std::size_t>(ncv)),
      z(static_cast<std::size_t>(n) * (static_cast<std::size_t>(nev) + 1));
  const double sigma = 0;
  dneupd_(&rvec, "A", select.data(), dr.data(), di.data(), z.data(), &ldv, &sigma, &sigma, workev.data(), "I", &n, "LM",
          &nev, &tol, resid.data(), &ncv, v.data(), &ldv, iparam, ipntr, workd.data(), workl.data(), &lworkl, &info, 1,
          1, 2);
  if (info != 0) throw NumericalError("floquet: ARPACK dneupd failed (info " + std::to_string(info) + ")");
  const int converged = std::min(iparam[4], nev + 1);
  if (s.complete && converged < nev)
    throw NumericalError("floquet: ARPACK converged " + std::to_string(converged) + " of " + std::to_string(nev) +
                         " multipliers");
  // Each multiplier's residual, measured: M applied to its Ritz vector z (a complex pair's
  // columns j, j + 1 hold Re z and Im z of the one with Im μ > 0; z has nev + 1 columns so that
  // a pair cut at the k-th keeps its imaginary part), ‖M z − μ z‖/(|μ| ‖z‖). A check that fails
  // when the Arnoldi factorization has lost accuracy, which ARPACK's estimate cannot see.
  std::vector<double> measured(static_cast<std::size_t>(converged), std::numeric_limits<double>::quiet_NaN());
  const auto column = [&](int j) {
    const double* c = &z[static_cast<std::size_t>(j) * static_cast<std::size_t>(n)];
    return std::vector<double>(c, c + n);
  };
  for (int i = 0; i < converged; ++i) {
    const double a = dr[static_cast<std::size_t>(i)], b = di[static_cast<std::size_t>(i)];
    const double modulus = std::hypot(a, b);
    if (b == 0) {
      const auto x = column(i), mx = apply_monodromy(law, chain, orbit, x);
      ++s.operator_applications;
      double r = 0;
      for (int k = 0; k < n; ++k) r += std::pow(mx[k] - a * x[k], 2);
      measured[static_cast<std::size_t>(i)] = std::sqrt(r) / (modulus * detail::euclidean_norm(x));
    } else if (b > 0 && i + 1 <= nev) {
      const auto x = column(i), y = column(i + 1);
      const auto mx = apply_monodromy(law, chain, orbit, x), my = apply_monodromy(law, chain, orbit, y);
      s.operator_applications += 2;
      double r = 0;
      for (int k = 0; k < n; ++k)
        r += std::pow(mx[k] - (a * x[k] - b * y[k]), 2) + std::pow(my[k] - (a * y[k] + b * x[k]), 2);
      const double norm = std::hypot(detail::euclidean_norm(x), detail::euclidean_norm(y));
      measured[static_cast<std::size_t>(i)] = std::sqrt(r) / (modulus * norm);
      if (i + 1 < converged) measured[static_cast<std::size_t>(i) + 1] = measured[static_cast<std::size_t>(i)];
    }
  }
  // The estimate of the Ritz value of dnaupd's nearest each multiplier.
  const auto estimate = [&](std::complex<double> mu) {
    std::size_t best = 0;
    for (std::size_t j = 1; j < bounds.size(); ++j)
      if (std::abs(std::complex(ritz_re[j], ritz_im[j]) - mu) < std::abs(std::complex(ritz_re[best], ritz_im[best]) - mu))
        best = j;
    return bounds[best] / std::abs(mu);
  };
  std::vector<std::pair<std::complex<double>, std::pair<double, double>>> found;  // μ, (estimate, measured)
  for (int i = 0; i < converged; ++i) {
    const std::complex<double> mu(dr[static_cast<std::size_t>(i)], di[static_cast<std::size_t>(i)]);
    found.push_back({mu, {estimate(mu), measured[static_cast<std::size_t>(i)]}});
  }
  // The Ritz values of real Arnoldi come in exact conjugate pairs, but the count kept can split one
  // (on a stable orbit every |μ| = 1, so which pair is last is arbitrary, and differs between BLAS
  // builds): a multiplier whose partner was cut gets it back, conj(μ), an eigenvalue as surely as μ.
  const std::size_t returned = found.size();
  for (std::size_t i = 0; i < returned; ++i) {
    const std::complex<double> mu = found[i].first;
    bool paired = mu.imag() == 0;
    for (std::size_t j = 0; j < returned && !paired; ++j)
      paired = j != i && std::abs(found[j].first - std::conj(mu)) <= 1e-8 * std::abs(mu);
    if (!paired) found.push_back({std::conj(mu), found[i].second});
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return std::abs(a.first) > std::abs(b.first); });
  s.multipliers.clear();
  s.ritz_residual = 0;
  bool trusted = true;  // every residual measured (not NaN) and within the limit
  for (const auto& [mu, checks] : found) {
    s.multipliers.push_back(mu);
    s.ritz_estimates.push_back(checks.first);
    s.ritz_residuals.push_back(checks.second);
    s.ritz_residual = std::max(s.ritz_residual, checks.second);
    trusted = trusted && checks.second <= config.ritz_residual_limit;
  }
  if (!trusted) s.complete = false;
  detail::decide_floquet_verdict(s, config.tolerance, config.unit_pair_window, orbit.period);
  s.reciprocal_error = std::numeric_limits<double>::quiet_NaN();
  s.product_error = std::numeric_limits<double>::quiet_NaN();
  return s;
}

}  // namespace granular
