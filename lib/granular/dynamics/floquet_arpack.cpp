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

#include "granular/dynamics/floquet.hpp"
#include "granular/error.hpp"

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
  if (info == 1 && iparam[4] < 1) return s;  // none converged

  const int rvec = 0;
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
  for (int i = 0; i < converged; ++i)
    s.multipliers.emplace_back(dr[static_cast<std::size_t>(i)], di[static_cast<std::size_t>(i)]);
  // The Ritz values of real Arnoldi come in exact conjugate pairs, but the count kept can split one
  // (on a stable orbit every |μ| = 1, so which pair is last is arbitrary, and differs between BLAS
  // builds): a multiplier whose partner was cut gets it back, conj(μ), an eigenvalue as surely as μ.
  const std::size_t returned = s.multipliers.size();
  for (std::size_t i = 0; i < returned; ++i) {
    const std::complex<double> mu = s.multipliers[i];
    bool paired = mu.imag() == 0;
    for (std::size_t j = 0; j < returned && !paired; ++j)
      paired = j != i && std::abs(s.multipliers[j] - std::conj(mu)) <= 1e-8 * std::abs(mu);
    if (!paired) s.multipliers.push_back(std::conj(mu));
  }
  std::sort(s.multipliers.begin(), s.multipliers.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });

  // The phase/family pair: up to two multipliers within the window of +1, left out of the verdict.
  std::vector<std::size_t> near_one;
  for (std::size_t i = 0; i < s.multipliers.size(); ++i)
    if (std::abs(s.multipliers[i] - 1.0) <= config.unit_pair_window) near_one.push_back(i);
  std::sort(near_one.begin(), near_one.end(), [&](std::size_t a, std::size_t b) {
    return std::abs(s.multipliers[a] - 1.0) < std::abs(s.multipliers[b] - 1.0);
  });
  if (near_one.size() > 2) near_one.resize(2);
  std::complex<double> worst = 0;
  for (std::size_t i = 0; i < s.multipliers.size(); ++i)
    if (std::find(near_one.begin(), near_one.end(), i) == near_one.end() && std::abs(s.multipliers[i]) > std::abs(worst))
      worst = s.multipliers[i];
  s.tolerance = config.tolerance;
  s.max_modulus = std::abs(worst);
  s.stable = s.max_modulus <= 1 + config.tolerance;
  s.growth_rate = std::log(s.max_modulus) / orbit.period;
  if (!s.stable) s.instability = std::abs(worst.imag()) <= config.tolerance * std::abs(worst) ? "real" : "oscillatory";
  for (const auto mu : s.multipliers) {
    double conjugate = std::numeric_limits<double>::infinity();
    for (const auto nu : s.multipliers) conjugate = std::min(conjugate, std::abs(nu - std::conj(mu)));
    s.conjugate_error = std::max(s.conjugate_error, conjugate / std::max(1.0, std::abs(mu)));
  }
  s.reciprocal_error = std::numeric_limits<double>::quiet_NaN();
  s.product_error = std::numeric_limits<double>::quiet_NaN();
  s.unit_pair_distance =
      near_one.size() == 2 ? std::abs(s.multipliers[near_one[1]] - 1.0) : std::numeric_limits<double>::quiet_NaN();
  return s;
}

}  // namespace granular
