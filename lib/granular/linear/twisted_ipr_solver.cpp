#include "granular/linear/twisted_ipr_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "granular/error.hpp"
#include "granular/linear/lapack.hpp"

namespace granular {

namespace {

constexpr std::size_t L = TwistedModeIpr::lanes;
constexpr double pivot_floor = 1e-290;  // a zero pivot becomes -pivot_floor (|e| ≤ 1 after scaling)
constexpr double negligible = 1e-60;    // |z| below this (z_r = 1) ends a recurrence

// IPR accumulation of one component; returns false once the component is negligible.
struct Sums {
  double z2 = 0, v2 = 0, v4 = 0;
  void add(double z, double s) {
    const double v = z * s;
    const double vv = v * v;
    z2 += z * z;
    v2 += vv;
    v4 += vv * vv;
  }
};

}  // namespace

TwistedModeIpr::TwistedModeIpr(TwistedIprConfig config) : config_(config), fallback_(LapackDriver::stevr) {
  if (!(config_.cluster_gap >= 0) || !(config_.cluster_gap < 1))
    throw InvalidInput("cluster_gap " + std::to_string(config_.cluster_gap) + ": must be in [0, 1)");
  if (!(config_.max_residual > 0)) throw InvalidInput("max_residual: must be > 0");
}

void TwistedModeIpr::reserve(std::size_t n) {
  if (n <= capacity_) return;
  capacity_ = n;
  for (auto* v : {&d_, &e_, &lambda_, &work_e_, &mass_, &stein_w_}) v->resize(n);
  for (auto* v : {&lplus_, &dplus_, &uminus_}) v->resize(n * L);
  isolated_.resize(n);
  stein_z_.resize(n * n);
  stein_work_.resize(5 * n);
  stein_iblock_.resize(n);
  stein_isplit_.resize(n);
  stein_iwork_.resize(3 * n);
  stein_ifail_.resize(n);
}

void TwistedModeIpr::solve(const SymTridiagonal& t, const std::vector<double>& s, std::vector<double>& omega2,
                           std::vector<double>& ipr) {
  const std::size_t n = t.size();
  if (n < 1) throw InvalidInput("eigen-solve of an empty matrix");
  if (s.size() != n) throw InvalidInput("inverse_sqrt_mass: size differs from the matrix");
  ++info_.solves;
  if (t.off_diagonal.size() + 1 != n) throw InvalidInput("tridiagonal matrix: off-diagonal needs n-1 entries");
  // max_abs() skips NaN (fmax), so check every entry: LAPACK may not return on NaN input.
  double scale = 0;
  for (double x : t.diagonal) scale = std::isfinite(x) ? std::fmax(scale, std::fabs(x)) : INFINITY;
  for (double x : t.off_diagonal) scale = std::isfinite(x) ? std::fmax(scale, std::fabs(x)) : INFINITY;
  if (!std::isfinite(scale)) throw NumericalError("dynamical matrix has a non-finite entry");
  if (scale > 0 && n >= 2) {
    reserve(n);
    const double inv = 1.0 / scale;
    for (std::size_t i = 0; i < n; ++i) d_[i] = t.diagonal[i] * inv;
    for (std::size_t i = 0; i + 1 < n; ++i) e_[i] = t.off_diagonal[i] * inv;
    double smax = 0;
    for (std::size_t i = 0; i < n; ++i) smax = std::fmax(smax, s[i]);
    bool ok = std::isfinite(smax) && smax > 0;
    if (ok) {
      for (std::size_t i = 0; i < n; ++i) mass_[i] = s[i] / smax;
      ipr.resize(n);
      ok = solve_scaled(n, ipr);
    }
    if (ok) {
      omega2.resize(n);
      for (std::size_t k = 0; k < n; ++k) omega2[k] = lambda_[k] * scale;
      return;
    }
  }
  ++info_.fallbacks;
  fallback_.solve(t, s, omega2, ipr);
}

bool TwistedModeIpr::solve_scaled(std::size_t n, std::vector<double>& ipr) {
  // 1. eigenvalues
  std::copy(d_.begin(), d_.begin() + static_cast<long>(n), lambda_.begin());
  std::copy(e_.begin(), e_.begin() + static_cast<long>(n - 1), work_e_.begin());
  const int ni = static_cast<int>(n);
  int info = 0;
  dsterf_(&ni, lambda_.data(), work_e_.data(), &info);
  if (info != 0) return false;
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isfinite(lambda_[k])) return false;
  const double norm = std::fmax(std::fabs(lambda_[0]), std::fabs(lambda_[n - 1]));
  if (!(norm > 0)) return false;
  residual_limit_ = config_.max_residual * static_cast<double>(n) * std::numeric_limits<double>::epsilon() * norm;

  // 2. isolated modes in batches, 3. clusters through dstein
  const double min_gap = config_.cluster_gap * norm;
  std::size_t isolated = 0;
  std::size_t k = 0;
  while (k < n) {
    std::size_t end = k + 1;  // the run [k, end) of modes closer than min_gap to a neighbour
    while (end < n && lambda_[end] - lambda_[end - 1] < min_gap) ++end;
    if (end - k == 1) {
      isolated_[isolated++] = k;
    } else {
      if (!cluster(n, k, end - k, ipr)) return false;
    }
    k = end;
  }
  for (std::size_t b = 0; b < isolated; b += L)
    if (!twisted_batch(n, isolated_.data() + b, std::min(L, isolated - b), ipr)) return false;
  info_.isolated_modes += isolated;
  return true;
}

bool TwistedModeIpr::twisted_batch(std::size_t n, const std::size_t* modes, std::size_t count,
                                   std::vector<double>& ipr) {
  const double* d = d_.data();
  const double* e = e_.data();
  double* lp = lplus_.data();
  double* dp = dplus_.data();
  double* um = uminus_.data();
  alignas(64) double sigma[L], piv[L], best[L];
  alignas(64) std::size_t twist[L];
  for (std::size_t l = 0; l < L; ++l) sigma[l] = lambda_[modes[std::min(l, count - 1)]];

  // stationary L D Lᵀ = T − σ from the top: D⁺_{i+1} = d_{i+1} − σ − e_i L⁺_i, L⁺_i = e_i / D⁺_i
  for (std::size_t l = 0; l < L; ++l) piv[l] = d[0] - sigma[l];
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double ei = e[i], dn = d[i + 1];
    for (std::size_t l = 0; l < L; ++l) {
      const double p = std::fabs(piv[l]) < pivot_floor ? -pivot_floor : piv[l];
      const double li = ei / p;
      dp[i * L + l] = p;
      lp[i * L + l] = li;
      piv[l] = (dn - sigma[l]) - ei * li;
    }
  }
  for (std::size_t l = 0; l < L; ++l) {
    dp[(n - 1) * L + l] = piv[l];
    best[l] = std::fabs(piv[l]);  // γ_{n-1} = D⁺_{n-1}
    twist[l] = n - 1;
  }
  // progressive U D Uᵀ from the bottom: U_i = e_i / D⁻_{i+1}; γ_i = D⁺_i − e_i U_i
  for (std::size_t l = 0; l < L; ++l) piv[l] = d[n - 1] - sigma[l];
  for (std::size_t i = n - 1; i-- > 0;) {
    const double ei = e[i], di = d[i];
    for (std::size_t l = 0; l < L; ++l) {
      const double p = std::fabs(piv[l]) < pivot_floor ? -pivot_floor : piv[l];
      const double ui = ei / p;
      um[i * L + l] = ui;
      piv[l] = (di - sigma[l]) - ei * ui;
      const double g = std::fabs(dp[i * L + l] - ei * ui);
      const bool better = g < best[l];
      best[l] = better ? g : best[l];
      twist[l] = better ? i : twist[l];
    }
  }
  // z_r = 1; z_i = −L⁺_i z_{i+1} above the twist, z_{i+1} = −U_i z_i below it
  const double* m = mass_.data();
  for (std::size_t l = 0; l < count; ++l) {
    const std::size_t r = twist[l];
    Sums sums;
    sums.add(1.0, m[r]);
    double z = 1.0;
    for (std::size_t i = r; i-- > 0;) {
      z = -lp[i * L + l] * z;
      if (!(std::fabs(z) >= negligible)) break;
      sums.add(z, m[i]);
    }
    z = 1.0;
    for (std::size_t i = r; i + 1 < n; ++i) {
      z = -um[i * L + l] * z;
      if (!(std::fabs(z) >= negligible)) break;
      sums.add(z, m[i + 1]);
    }
    const double residual = best[l] / std::sqrt(sums.z2);
    const double p = sums.v4 / (sums.v2 * sums.v2);
    if (!(residual <= residual_limit_) || !(p > 0 && p <= 1 + 1e-12)) return false;
    ipr[modes[l]] = std::fmin(p, 1.0);
  }
  return true;
}

bool TwistedModeIpr::cluster(std::size_t n, std::size_t first, std::size_t count, std::vector<double>& ipr) {
  const int ni = static_cast<int>(n), m = static_cast<int>(count);
  for (std::size_t j = 0; j < count; ++j) {
    stein_w_[j] = lambda_[first + j];
    stein_iblock_[j] = 1;
  }
  stein_isplit_[0] = ni;
  int info = 0;
  dstein_(&ni, d_.data(), e_.data(), &m, stein_w_.data(), stein_iblock_.data(), stein_isplit_.data(),
          stein_z_.data(), &ni, stein_work_.data(), stein_iwork_.data(), stein_ifail_.data(), &info);
  if (info != 0) return false;
  for (std::size_t j = 0; j < count; ++j) {
    const double* z = stein_z_.data() + j * n;
    Sums sums;
    for (std::size_t i = 0; i < n; ++i) sums.add(z[i], mass_[i]);
    const double p = sums.v4 / (sums.v2 * sums.v2);
    if (!(p > 0 && p <= 1 + 1e-12)) return false;
    ipr[first + j] = std::fmin(p, 1.0);
  }
  ++info_.clusters;
  info_.cluster_modes += count;
  return true;
}

}  // namespace granular
