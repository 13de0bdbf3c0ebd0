#include "granular/linear/detail/twisted_ipr_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

#include "granular/error.hpp"
#include "granular/linear/detail/cluster_basis.hpp"
#include "granular/linear/detail/lapack.hpp"
#include "granular/linear/detail/rational_ql.hpp"

namespace granular {

namespace {

constexpr std::size_t L = TwistedModeIpr::lanes;

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
    throw InvalidInput("cluster_gap", " " + std::to_string(config_.cluster_gap) + ": must be in [0, 1)");
  if (!(config_.max_residual > 0)) throw InvalidInput("max_residual", ": must be > 0");
}

void TwistedModeIpr::reserve(std::size_t n) {
  if (n <= capacity_) return;
  capacity_ = n;
  for (Slot& slot : slots_)
    for (auto* v : {&slot.d, &slot.e, &slot.e2, &slot.lambda, &slot.mass}) v->resize(n);
  stein_w_.resize(n);
  lane_work_.reserve(n);
  isolated_.resize(n);
  stein_work_.resize(5 * n);  // stein_z_ grows to the largest cluster's vectors (N × N is 80 GB at N = 1e5)
  stein_iblock_.resize(n);
  stein_isplit_.resize(n);
  stein_iwork_.resize(3 * n);
  stein_ifail_.resize(n);
}

void TwistedModeIpr::solve(const SymTridiagonal& t, const std::vector<double>& s, std::vector<double>& omega2,
                           std::vector<double>& ipr) {
  const ModeIprTask task{&t, &s, &omega2, &ipr};
  solve_group({&task, 1});
}

void TwistedModeIpr::solve_batch(std::span<const ModeIprTask> tasks) {
  for (std::size_t first = 0; first < tasks.size(); first += group)
    solve_group(tasks.subspan(first, std::min(group, tasks.size() - first)));
}

bool TwistedModeIpr::load(Slot& slot, const ModeIprTask& task) {
  const SymTridiagonal& t = *task.matrix;
  const std::vector<double>& s = *task.inverse_sqrt_mass;
  const std::size_t n = t.size();
  if (n < 1) throw InvalidInput("eigen-solve of an empty matrix");
  if (s.size() != n) throw InvalidInput("inverse_sqrt_mass", ": size differs from the matrix");
  if (t.off_diagonal.size() + 1 != n) throw InvalidInput("tridiagonal matrix: off-diagonal needs n-1 entries");
  // max_abs() skips NaN (fmax), so check every entry: LAPACK may not return on NaN input.
  double scale = 0;
  for (double x : t.diagonal) scale = std::isfinite(x) ? std::fmax(scale, std::fabs(x)) : INFINITY;
  for (double x : t.off_diagonal) scale = std::isfinite(x) ? std::fmax(scale, std::fabs(x)) : INFINITY;
  if (!std::isfinite(scale)) throw NumericalError("dynamical matrix has a non-finite entry");
  slot.n = n;
  slot.scale = scale;
  if (!(scale > 0) || n < 2) return false;
  double smax = 0;
  for (double x : s) smax = std::fmax(smax, x);
  if (!std::isfinite(smax) || !(smax > 0)) return false;
  const double inv = 1.0 / scale;
  for (std::size_t i = 0; i < n; ++i) {
    slot.d[i] = slot.lambda[i] = t.diagonal[i] * inv;
    slot.mass[i] = s[i] / smax;
  }
  for (std::size_t i = 0; i + 1 < n; ++i) {
    slot.e[i] = t.off_diagonal[i] * inv;
    slot.e2[i] = slot.e[i] * slot.e[i];
  }
  return true;
}

void TwistedModeIpr::solve_group(std::span<const ModeIprTask> tasks) {
  const std::size_t count = tasks.size();
  std::size_t n_max = 0;
  for (const ModeIprTask& t : tasks) n_max = std::max(n_max, t.matrix->size());
  reserve(n_max);
  for (std::size_t j = 0; j < count; ++j) slots_[j].ok = load(slots_[j], tasks[j]);

  // 1. eigenvalues: the chains' QL iterations in vector lanes
  detail::QlChain ql[group];
  std::size_t loaded = 0;
  for (std::size_t j = 0; j < count; ++j)
    if (slots_[j].ok) ql[loaded++] = {slots_[j].lambda.data(), slots_[j].e2.data(), slots_[j].n};
  if (loaded == 1) detail::rational_ql(ql[0]);
  else detail::rational_ql_lanes({ql, loaded}, ql_work_);

  // 2.-4. modes, per chain
  for (std::size_t j = 0, q = 0; j < count; ++j) {
    Slot& slot = slots_[j];
    const ModeIprTask& task = tasks[j];
    ++info_.solves;
    bool ok = slot.ok && ql[q].converged;
    q += slot.ok;
    if (ok) {
      std::sort(slot.lambda.begin(), slot.lambda.begin() + static_cast<long>(slot.n));
      task.ipr->resize(slot.n);
      ok = solve_modes(slot, *task.ipr);
    }
    if (ok) {
      task.omega2->resize(slot.n);
      for (std::size_t k = 0; k < slot.n; ++k) (*task.omega2)[k] = slot.lambda[k] * slot.scale;
    } else {
      ++info_.fallbacks;
      fallback_.solve(*task.matrix, *task.inverse_sqrt_mass, *task.omega2, *task.ipr);
    }
  }
}

bool TwistedModeIpr::solve_modes(const Slot& slot, std::vector<double>& ipr) {
  const std::size_t n = slot.n;
  const double* lambda = slot.lambda.data();
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isfinite(lambda[k])) return false;
  const double norm = std::fmax(std::fabs(lambda[0]), std::fabs(lambda[n - 1]));
  if (!(norm > 0)) return false;
  residual_limit_ = config_.max_residual * static_cast<double>(n) * std::numeric_limits<double>::epsilon() * norm;

  const double min_gap = config_.cluster_gap * norm;
  std::size_t isolated = 0;
  std::size_t k = 0;
  while (k < n) {
    std::size_t end = k + 1;  // the run [k, end) of modes closer than min_gap to a neighbour
    while (end < n && lambda[end] - lambda[end - 1] < min_gap) ++end;
    if (end - k == 1) {
      isolated_[isolated++] = k;
    } else if (!cluster(slot, k, end - k, ipr)) {
      return false;
    }
    k = end;
  }
  for (std::size_t b = 0; b < isolated; b += L)
    if (!twisted_batch(slot, isolated_.data() + b, std::min(L, isolated - b), ipr)) return false;
  info_.isolated_modes += isolated;
  return true;
}

bool TwistedModeIpr::twisted_batch(const Slot& slot, const std::size_t* modes, std::size_t count,
                                   std::vector<double>& ipr) {
  alignas(64) double sigma[L];
  detail::TwistedSums sums[L];
  for (std::size_t l = 0; l < L; ++l) sigma[l] = slot.lambda[modes[std::min(l, count - 1)]];
  detail::twisted_lanes(slot.d.data(), slot.e.data(), slot.mass.data(), slot.n, sigma, lane_work_, sums);
  for (std::size_t l = 0; l < count; ++l) {
    const double residual = sums[l].gamma / std::sqrt(sums[l].z2);
    const double p = sums[l].v4 / (sums[l].v2 * sums[l].v2);
    if (!(residual <= residual_limit_) || !(p > 0 && p <= 1 + 1e-12)) return false;
    ipr[modes[l]] = std::fmin(p, 1.0);
  }
  return true;
}

// dstein's basis of a cluster is arbitrary: a pair of modes degenerate to 1e-16 on two isolated
// light beads comes out as their sum and difference (IPR ≈ P/2 each) as readily as one bead
// each (IPR = P). Rotate it to the most localized orthonormal basis instead — Jacobi sweeps of
// plane rotations, each maximizing Σ_i (x_i⁴ + y_i⁴) over the displacement components of the
// pair (closed form: 4θ = atan2(2Σuv, Σ(u² − v²)), u = a² − b², v = 2ab). This basis is a
// property of the subspace, not of the solver, and it is the one an infinitesimal physical
// imperfection would select; LAPACK's drivers return it too for decoupled lumps.
void TwistedModeIpr::localize(const Slot& slot, std::size_t count) {
  const std::size_t n = slot.n;
  // The sweeps run on the beads where some vector of the cluster is not negligible, gathered
  // side by side: a cluster's localized modes sit on a few isolated beads, a few beads each, of a
  // chain of N. An entry below 1e-10 of the cluster's largest is left as it is; rotated, it would
  // stay below 1.5e-10 of it, so the vectors' norms move by less than N · 1e-20 (their IPRs by
  // less, at rounding level: tests/linear/twisted_ipr_solver_test.cpp), and its share of the
  // sums below, (1e-10)⁴, is far below their rounding.
  row_largest_.assign(n, 0.0);  // per bead, the largest |z| of the cluster's vectors
  double* __restrict row = row_largest_.data();
  for (std::size_t j = 0; j < count; ++j) {
    const double* __restrict z = stein_z_.data() + j * n;
    for (std::size_t i = 0; i < n; ++i) row[i] = std::fmax(row[i], std::fabs(z[i]));
  }
  const double floor = 1e-10 * *std::max_element(row_largest_.begin(), row_largest_.end());
  support_.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (row[i] >= floor) support_.push_back(i);
  const std::size_t s = support_.size();
  gathered_.resize(s * (count + 1));
  double* m = gathered_.data() + s * count;
  for (std::size_t p = 0; p < s; ++p) m[p] = slot.mass[support_[p]];
  for (std::size_t j = 0; j < count; ++j)
    for (std::size_t p = 0; p < s; ++p) gathered_[j * s + p] = stein_z_[j * n + support_[p]];
  for (int sweep = 0; sweep < 50; ++sweep) {
    double largest = 0;
    for (std::size_t j = 0; j + 1 < count; ++j)
      for (std::size_t k = j + 1; k < count; ++k) {
        double* a = gathered_.data() + j * s;
        double* b = gathered_.data() + k * s;
        double suv = 0, suu_vv = 0;
        for (std::size_t i = 0; i < s; ++i) {
          const double x = a[i] * m[i], y = b[i] * m[i];
          const double u = x * x - y * y, v = 2 * x * y;
          suv += u * v;
          suu_vv += u * u - v * v;
        }
        const double theta = 0.25 * std::atan2(2 * suv, suu_vv);
        if (!(std::fabs(theta) > 1e-14)) continue;
        largest = std::fmax(largest, std::fabs(theta));
        const double c = std::cos(theta), sn = std::sin(theta);
        for (std::size_t i = 0; i < s; ++i) {
          const double x = a[i], y = b[i];
          a[i] = c * x + sn * y;
          b[i] = -sn * x + c * y;
        }
      }
    if (!(largest > 1e-12)) break;
  }
  for (std::size_t j = 0; j < count; ++j)
    for (std::size_t p = 0; p < s; ++p) stein_z_[j * n + support_[p]] = gathered_[j * s + p];
}

bool TwistedModeIpr::cluster(const Slot& slot, std::size_t first, std::size_t count, std::vector<double>& ipr) {
  const std::size_t n = slot.n;
  if (stein_z_.size() < n * count) stein_z_.resize(n * count);  // the cluster's vectors only
  const double tolerance = residual_limit_ * std::sqrt(static_cast<double>(count));
  if (!detail::cluster_basis(slot.d.data(), slot.e.data(), n, slot.lambda.data() + first, count, tolerance,
                             stein_z_.data(), cluster_work_)) {
    ++info_.cluster_dstein;  // LAPACK's dstein instead: inverse iteration vector by vector
    const int ni = static_cast<int>(n), m = static_cast<int>(count);
    for (std::size_t j = 0; j < count; ++j) {
      stein_w_[j] = slot.lambda[first + j];
      stein_iblock_[j] = 1;
    }
    stein_isplit_[0] = ni;
    int info = 0;
    dstein_(&ni, slot.d.data(), slot.e.data(), &m, stein_w_.data(), stein_iblock_.data(), stein_isplit_.data(),
            stein_z_.data(), &ni, stein_work_.data(), stein_iwork_.data(), stein_ifail_.data(), &info);
    if (info != 0) return false;
  }
  localize(slot, count);
  // Mode numbers count by frequency. Inside a cluster the localized vectors are numbered by their
  // Rayleigh quotients zᵀTz / zᵀz: which IPR goes with which mode number then depends on the
  // subspace, not on the basis the cluster's solve started from.
  cluster_order_.clear();
  for (std::size_t j = 0; j < count; ++j) {
    const double* z = stein_z_.data() + j * n;
    double zz = 0, ztz = 0, largest = -1;
    std::size_t centre = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double tz = slot.d[i] * z[i];
      if (i > 0) tz += slot.e[i - 1] * z[i - 1];
      if (i + 1 < n) tz += slot.e[i] * z[i + 1];
      zz += z[i] * z[i];
      ztz += z[i] * tz;
      if (std::fabs(z[i]) > largest) largest = std::fabs(z[i]), centre = i;
    }
    cluster_order_.push_back({ztz / zz, centre, j});
  }
  std::sort(cluster_order_.begin(), cluster_order_.end());
  // Quotients closer than their rounding (here 1e-13 max|λ|) give no order: such vectors are
  // numbered by where they sit, so that a rounding-level change anywhere cannot swap them.
  const double tie = 1e-13 * std::fmax(std::fabs(slot.lambda[0]), std::fabs(slot.lambda[n - 1]));
  for (std::size_t b = 0; b < count;) {
    std::size_t e = b + 1;
    while (e < count && std::get<0>(cluster_order_[e]) - std::get<0>(cluster_order_[e - 1]) < tie) ++e;
    std::sort(cluster_order_.begin() + static_cast<long>(b), cluster_order_.begin() + static_cast<long>(e),
              [](const auto& x, const auto& y) { return std::get<1>(x) < std::get<1>(y); });
    b = e;
  }
  for (std::size_t j = 0; j < count; ++j) {
    const double* z = stein_z_.data() + std::get<2>(cluster_order_[j]) * n;
    Sums sums;
    for (std::size_t i = 0; i < n; ++i) sums.add(z[i], slot.mass[i]);
    const double p = sums.v4 / (sums.v2 * sums.v2);
    if (!(p > 0 && p <= 1 + 1e-12)) return false;
    ipr[first + j] = std::fmin(p, 1.0);
  }
  ++info_.clusters;
  info_.cluster_modes += count;
  return true;
}

}  // namespace granular
