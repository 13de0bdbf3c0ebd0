#include "granular/linear/detail/sturm_bisection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "granular/error.hpp"
#include "granular/linear/detail/lapack.hpp"
#include "granular/linear/detail/sturm_count.hpp"
#include "granular/linear/tridiagonal_operator.hpp"

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

namespace granular {

namespace {

using detail::sturm_counts;
using detail::sturm_pivot_floor;

#if defined(__AVX512F__)
/// The Sturm count of detail/sturm_count.hpp with AVX-512 and the division b²/p replaced by
/// b² · r, r = 1/p from rcp14 and two Newton steps (2⁻¹⁴ → 2⁻⁵⁶ relative, i.e. within an ulp of
/// the quotient): a Sturm count is exact for a matrix perturbed by O(ε) per step anyway, and
/// vdivpd's throughput, not the memory, bounds the sweep. L lanes = L/8 independent vector chains.
template <int L>
void count_block_avx512(const SymTridiagonal& t, double pivmin, const double* shift, long* count) {
  static_assert(L % 8 == 0);
  constexpr int V = L / 8;
  const std::size_t n = t.size();
  const double* a = t.diagonal.data();
  const double* b = t.off_diagonal.data();
  const __m512d pm = _mm512_set1_pd(pivmin), npm = _mm512_set1_pd(-pivmin), zero = _mm512_setzero_pd(),
                one = _mm512_set1_pd(1.0);
  __m512d p[V], s[V], c[V];
  for (int v = 0; v < V; ++v) {
    s[v] = _mm512_loadu_pd(shift + 8 * v);
    __m512d q = _mm512_sub_pd(_mm512_set1_pd(a[0]), s[v]);
    q = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(_mm512_abs_pd(q), pm, _CMP_LE_OQ), q, npm);
    p[v] = q;
    c[v] = _mm512_maskz_mov_pd(_mm512_cmp_pd_mask(q, zero, _CMP_LT_OQ), one);
  }
  for (std::size_t i = 1; i < n; ++i) {
    const __m512d ai = _mm512_set1_pd(a[i]), b2 = _mm512_set1_pd(b[i - 1] * b[i - 1]);
    for (int v = 0; v < V; ++v) {
      __m512d r = _mm512_maskz_rcp14_pd(0xFF, p[v]);  // maskz: GCC 12 -Wmaybe-uninitialized
      r = _mm512_fmadd_pd(r, _mm512_fnmadd_pd(p[v], r, one), r);
      r = _mm512_fmadd_pd(r, _mm512_fnmadd_pd(p[v], r, one), r);
      __m512d q = _mm512_fnmadd_pd(b2, r, _mm512_sub_pd(ai, s[v]));
      q = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(_mm512_abs_pd(q), pm, _CMP_LE_OQ), q, npm);
      p[v] = q;
      c[v] = _mm512_mask_add_pd(c[v], _mm512_cmp_pd_mask(q, zero, _CMP_LT_OQ), c[v], one);
    }
  }
  alignas(64) double out[L];
  for (int v = 0; v < V; ++v) _mm512_store_pd(out + 8 * v, c[v]);
  for (int j = 0; j < L; ++j) count[j] = static_cast<long>(out[j]);
}
#endif

#if defined(__GNUC__)
/// The Sturm count of detail/sturm_count.hpp in explicit 4-wide vectors (GCC/Clang vector
/// extensions: AVX2 where the build has it, SSE pairs else), with the very same IEEE operations per
/// lane, so its counts equal the scalar kernel's bit for bit. Why not leave it to the compiler: GCC
/// vectorized sturm_counts<32> but left <8> and <16> scalar (vdivsd), 4.5× slower per shift.
/// L lanes = L/4 independent division chains, enough to cover the divider's latency from L = 16.
template <int L>
void count_block_vector(const SymTridiagonal& t, double pivmin, const double* shift, long* count) {
  static_assert(L % 4 == 0);
  using v4 = detail::SturmLanes;
  using m4 = detail::SturmMasks;
  constexpr int V = L / 4;
  const std::size_t n = t.size();
  const double* a = t.diagonal.data();
  const double* b = t.off_diagonal.data();
  const v4 zero{}, pm = zero + pivmin;
  v4 p[V], s[V];
  m4 c[V];
  auto guard = [&](v4 q) { return detail::sturm_guard(q, pm); };
  for (int v = 0; v < V; ++v) {
    for (int k = 0; k < 4; ++k) s[v][k] = shift[4 * v + k];
    p[v] = guard((zero + a[0]) - s[v]);
    c[v] = -(p[v] < zero);
  }
  for (std::size_t i = 1; i < n; ++i) {
    const v4 ai = zero + a[i], b2 = zero + b[i - 1] * b[i - 1];
    for (int v = 0; v < V; ++v) {
      p[v] = guard((ai - s[v]) - b2 / p[v]);
      c[v] -= p[v] < zero;
    }
  }
  for (int v = 0; v < V; ++v)
    for (int k = 0; k < 4; ++k) count[4 * v + k] = static_cast<long>(c[v][k]);
}
#endif

/// One sweep of L shifts: the AVX-512 kernel where the build has it, else the vector lanes.
template <int L>
void sweep(const SymTridiagonal& t, double pivmin, const double* shift, long* count) {
#if defined(__AVX512F__)
  count_block_avx512<L>(t, pivmin, shift, count);
#elif defined(__GNUC__)
  count_block_vector<L>(t, pivmin, shift, count);
#else
  sturm_counts<L>(t, pivmin, shift, count);
#endif
}

void count_many(const SymTridiagonal& t, double pivmin, const std::vector<double>& shifts, std::vector<long>& counts) {
  constexpr int L = 32;
  const std::size_t m = shifts.size();
  counts.assign(m, 0);
  for (std::size_t j0 = 0; j0 < m; j0 += L) {
    double s[L];
    long c[L];
    const std::size_t k = std::min<std::size_t>(L, m - j0);
    for (std::size_t j = 0; j < L; ++j) s[j] = shifts[j0 + std::min(j, k - 1)];  // pad with a repeat
    if (k <= 8) {
      sweep<8>(t, pivmin, s, c);
    } else if (k <= 16) {
      sweep<16>(t, pivmin, s, c);
    } else {
      sweep<32>(t, pivmin, s, c);
    }
    for (std::size_t j = 0; j < k; ++j) counts[j0 + j] = c[j];
  }
}

}  // namespace

std::vector<long> count_below_many(const SymTridiagonal& t, const std::vector<double>& shifts) {
  std::vector<long> c;
  count_many(t, sturm_pivot_floor(t), shifts, c);
  return c;
}

std::vector<double> bisect_eigenvalues(const SymTridiagonal& t, int first, int last, double relative_width,
                                       double isolated_width, std::vector<double>* brackets, double centre,
                                       std::size_t nearest) {
  const int n = static_cast<int>(t.size());
  if (first < 1 || last < first || last > n)
    throw InvalidInput("eigenvalue index range " + std::to_string(first) + ".." + std::to_string(last) +
                       ": must satisfy 1 <= first <= last <= N = " + std::to_string(n));
  const double pivmin = sturm_pivot_floor(t);
  auto [glo, ghi] = gershgorin_bounds(t);
  const double pad = 4 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(glo), std::fabs(ghi)) + 2 * pivmin;
  glo -= pad;
  ghi += pad;
  const int m = last - first + 1;
  // Lane j brackets eigenvalue number first + j: count(lo) < first + j <= count(hi).
  std::vector<double> lo(m, glo), hi(m, ghi);
  std::vector<long> count_lo(m, 0), count_hi(m, n);  // counts at the bracket ends
  // With `nearest`: the lanes still wanted, those that may be among the K nearest the centre in
  // √λ and their neighbours by index (recomputed every pass; a lane once unwanted stays so).
  std::vector<char> wanted(m, 1);
  const bool ranked = nearest > 0 && std::isfinite(centre) && static_cast<std::size_t>(m) > nearest + 2;
  const double root_centre = std::sqrt(std::max(0.0, centre));
  auto settle_wanted = [&] {
    std::vector<double> near(m), far(m);  // each bracket's least and greatest distance in √λ
    for (int j = 0; j < m; ++j) {
      const double a = std::sqrt(std::max(0.0, lo[j])) - root_centre, b = std::sqrt(std::max(0.0, hi[j])) - root_centre;
      near[j] = a <= 0 && b >= 0 ? 0 : std::min(std::fabs(a), std::fabs(b));
      far[j] = std::max(std::fabs(a), std::fabs(b));
    }
    std::vector<char> may(m, 0);  // fewer than K lanes certainly nearer
    for (int j = 0; j < m; ++j) {
      std::size_t nearer = 0;
      for (int i = 0; i < m; ++i) nearer += i != j && far[i] < near[j];
      may[j] = nearer < nearest;
    }
    for (int j = 0; j < m; ++j) wanted[j] = wanted[j] && (may[j] || (j > 0 && may[j - 1]) || (j + 1 < m && may[j + 1]));
  };
  auto done = [&](int j) {
    if (!wanted[j]) return true;
    const double scale = std::max(std::fabs(lo[j]), std::fabs(hi[j])), width = hi[j] - lo[j];
    if (width <= relative_width * scale + 4 * pivmin) return true;
    // Coarse is enough when the bracket holds this eigenvalue alone and the neighbouring lanes'
    // brackets are ≥ 2 widths away: inverse iteration from the midpoint then gains ≥ 5× a sweep
    // and the Rayleigh quotient, kept inside the bracket, converges cubically from there.
    const bool alone = count_lo[j] == first + j - 1 && count_hi[j] == first + j;
    const double below = j > 0 ? lo[j] - hi[j - 1] : 2 * width, above = j + 1 < m ? lo[j + 1] - hi[j] : 2 * width;
    return alone && width <= isolated_width * scale && std::min(below, above) >= 2 * width;
  };
  std::vector<double> shifts;
  std::vector<long> counts;
  std::vector<std::pair<int, int>> groups;
  for (int pass = 0; pass < 4000; ++pass) {
    if (ranked && pass > 0) settle_wanted();
    shifts.clear();
    // Lanes with the same bracket form a group; its g lanes spread g shifts evenly over it.
    groups.clear();
    int lanes = 0;
    for (int j = 0; j < m;) {
      int k = j;
      while (k + 1 < m && lo[k + 1] == lo[j] && hi[k + 1] == hi[j]) ++k;
      bool any = false;
      for (int r = j; r <= k; ++r) any = any || !done(r);
      if (any) {
        groups.emplace_back(j, k - j + 1);
        lanes += k - j + 1;
      }
      j = k + 1;
    }
    if (groups.empty()) break;
    // A sweep of up to 16 shifts costs what one of 1 does (the divider's latency, not its
    // throughput, bounds it): a pass with few lanes left gives each group more shifts.
    const int spread = lanes <= 8 ? 16 / lanes : 1;
    for (const auto& [j, g] : groups)
      for (int r = 1; r <= g * spread; ++r) shifts.push_back(lo[j] + (hi[j] - lo[j]) * r / (g * spread + 1));
    // First pass with a centre: 16 pairs of shifts around it, 4× closer each, instead of even
    // ones over the whole spectrum (three passes fewer for a run of modes near the centre).
    if (pass == 0 && std::isfinite(centre) && centre > glo && centre < ghi) {
      shifts.clear();
      const double span = ghi - glo;
      for (int k = 0; k < 16; ++k) {
        const double d = 0.5 * span * std::pow(0.25, k);
        shifts.push_back(std::max(glo, centre - d));
        shifts.push_back(std::min(ghi, centre + d));
      }
    }
    count_many(t, pivmin, shifts, counts);
    // Every count narrows every bracket: λ_k < s ⇔ count(s) ≥ k.
    for (std::size_t q = 0; q < shifts.size(); ++q) {
      const double s = shifts[q];
      const long c = counts[q];
      for (int j = 0; j < m; ++j) {
        const long k = first + j;
        if (c >= k) {
          if (s < hi[j]) {
            hi[j] = s;
            count_hi[j] = c;
          }
        } else if (s > lo[j]) {
          lo[j] = s;
          count_lo[j] = c;
        }
      }
    }
  }
  std::vector<double> values(m);
  for (int j = 0; j < m; ++j) {
    if (!done(j)) throw NumericalError("bisection did not converge for eigenvalue " + std::to_string(first + j));
    values[j] = 0.5 * (lo[j] + hi[j]);
  }
  if (brackets) {
    brackets->resize(2 * static_cast<std::size_t>(m));
    for (int j = 0; j < m; ++j) {
      (*brackets)[2 * j] = lo[j];
      (*brackets)[2 * j + 1] = hi[j];
    }
  }
  return values;
}

Eigen::MatrixXd inverse_iteration(const SymTridiagonal& t, std::vector<double>& values) {
  const std::size_t n = t.size(), m = values.size();
  Eigen::MatrixXd z(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
  if (m == 0) return z;
  const double norm = t.max_abs();
  const double eps = std::numeric_limits<double>::epsilon();
  // Vectors whose eigenvalues are closer than this are made orthogonal explicitly; farther ones
  // already are, to ~eps‖T‖/gap, by the accuracy of each vector.
  const double cluster = kClusterGap * norm;
  ShiftInvertOperator lu;
  std::vector<double> tw(n);
  std::uint64_t seed = 0x2545F4914F6CDD1Dull;
  for (std::size_t j = 0; j < m; ++j) {
    double* x = z.col(static_cast<Eigen::Index>(j)).data();
    for (std::size_t i = 0; i < n; ++i) {  // fixed pseudo-random start (xorshift), reproducible
      seed ^= seed << 13;
      seed ^= seed >> 7;
      seed ^= seed << 17;
      x[i] = static_cast<double>(seed >> 11) * 0x1.0p-53 - 0.5;
    }
    lu.factorize(t, values[j]);
    std::size_t first_close = j;
    while (first_close > 0 && values[j] - values[first_close - 1] < cluster) --first_close;
    double residual = std::numeric_limits<double>::infinity();
    for (int it = 0; it < 6 && residual > kResidualTarget * norm; ++it) {
      lu.solve(x);
      for (std::size_t k = first_close; k < j; ++k) {  // Gram–Schmidt within the cluster
        const double* y = z.col(static_cast<Eigen::Index>(k)).data();
        double dot = 0;
        for (std::size_t i = 0; i < n; ++i) dot += x[i] * y[i];
        for (std::size_t i = 0; i < n; ++i) x[i] -= dot * y[i];
      }
      double s2 = 0;
      for (std::size_t i = 0; i < n; ++i) s2 += x[i] * x[i];
      const double inv = 1 / std::sqrt(s2);
      for (std::size_t i = 0; i < n; ++i) x[i] *= inv;
      // Rayleigh quotient and residual ‖Tx − ρx‖ of the unit vector.
      t.multiply(x, tw.data());
      double rho = 0;
      for (std::size_t i = 0; i < n; ++i) rho += x[i] * tw[i];
      double r2 = 0;
      for (std::size_t i = 0; i < n; ++i) r2 += (tw[i] - rho * x[i]) * (tw[i] - rho * x[i]);
      residual = std::sqrt(r2);
      if (it > 0 || residual <= kResidualTarget * norm) values[j] = rho;
    }
    if (!(residual <= 1e3 * eps * norm))
      throw NumericalError("inverse iteration: eigenvector " + std::to_string(j) + " did not converge (residual " +
                           std::to_string(residual / norm) + " of ||T||)");
  }
  return z;
}

namespace {

/// One group of lanes of lane_inverse_iteration; results go to columns first… of z (if kept) and
/// to options.ipr / options.residual at the same positions.
void lane_group(const SymTridiagonal& t, std::vector<double>& values, const std::vector<double>* brackets,
                const LaneOptions& options, Eigen::MatrixXd& z, std::size_t first) {
  const std::size_t n = t.size(), m = values.size();
  const double norm = t.max_abs(), eps = std::numeric_limits<double>::epsilon();
  // Lanes closer than this (or with touching brackets) are made orthogonal explicitly: their
  // shifts cannot tell them apart. Lanes farther apart converge to distinct eigenvectors inside
  // disjoint brackets, orthogonal to ~ε‖T‖/gap without help.
  const double floor = eps * norm, target = kResidualTarget * norm, cluster = kClusterGap * norm;
  const double* a = t.diagonal.data();
  const double* e = t.off_diagonal.data();
  const std::size_t L = m;
  std::vector<double> x(n * L), inv_d(n * L);  // row-major: entry i of lane j at i L + j
  std::uint64_t seed = 0x2545F4914F6CDD1Dull;
  for (auto& v : x) {  // fixed pseudo-random start (xorshift), reproducible
    seed ^= seed << 13;
    seed ^= seed >> 7;
    seed ^= seed << 17;
    v = static_cast<double>(seed >> 11) * 0x1.0p-53 - 0.5;
  }
  std::vector<double> mu(values), rho(values), res(m, std::numeric_limits<double>::infinity()), s2(m), xtx(m);
  const std::vector<double> start(values);
  const double slack = kResidualTarget * norm;
  auto inside = [&](std::size_t j, double v) {
    if (!brackets) return std::fabs(v - start[j]) < cluster;
    return v >= (*brackets)[2 * j] - slack && v <= (*brackets)[2 * j + 1] + slack;
  };
  bool converged = false;
  // One sweep = 2 passes over the N × m lanes: factor + forward solve (scaling the previous
  // vector to unit length on the fly); backward solve + ‖y‖² + yᵀTy (T y lags one row behind).
  // Converged by the free residual estimate ‖x_old‖/‖y‖ of the solve (T − μ) y = x_old, then
  // confirmed by one pass computing ‖T x − ρ x‖ exactly.
  std::vector<double> sc(m, 1.0);                                       // the vector of lane j is sc[j] · x[· L + j]
  auto t_times = [&](std::size_t i, const double* xi, std::size_t j) {  // (T x)_i of lane j; xi = &x[i L]
    double tx = a[i] * xi[j];
    if (i > 0) tx += e[i - 1] * (xi - L)[j];  // (not xi[j - L]: j - L wraps around as an unsigned offset)
    if (i + 1 < n) tx += e[i] * (xi + L)[j];
    return tx;
  };
  auto true_residuals = [&] {
    std::fill(res.begin(), res.end(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const double* xi = &x[i * L];
      for (std::size_t j = 0; j < L; ++j) {
        const double r = sc[j] * (t_times(i, xi, j) - rho[j] * xi[j]);
        res[j] += r * r;
      }
    }
    bool ok = true;
    for (std::size_t j = 0; j < L; ++j) {
      res[j] = std::sqrt(res[j]);
      ok = ok && res[j] <= target && inside(j, rho[j]);
    }
    return ok;
  };
  auto norms_and_quotients = [&] {  // ‖x‖² into s2, xᵀTx into xtx (a separate pass; after GS only)
    std::fill(s2.begin(), s2.end(), 0.0);
    std::fill(xtx.begin(), xtx.end(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const double* xi = &x[i * L];
      for (std::size_t j = 0; j < L; ++j) {
        s2[j] += xi[j] * xi[j];
        xtx[j] += xi[j] * t_times(i, xi, j);
      }
    }
  };
  for (int sweep = 0; sweep < 8 && !converged; ++sweep) {
    // forward: factor T − μI = L D Lᵀ and solve L y = sc ⊙ x
    for (std::size_t j = 0; j < L; ++j) {
      double d = a[0] - mu[j];
      if (std::fabs(d) < floor) d = d < 0 ? -floor : floor;
      inv_d[j] = 1 / d;
      x[j] *= sc[j];
    }
    for (std::size_t i = 1; i < n; ++i) {
      const double ei = e[i - 1], ai = a[i];
      double* xi = &x[i * L];
      const double* xp = &x[(i - 1) * L];
      double* di = &inv_d[i * L];
      const double* dp = &inv_d[(i - 1) * L];
#if defined(__GNUC__) && !defined(__clang__)  // clang warns about the GCC pragma
#pragma GCC ivdep
#endif
      for (std::size_t j = 0; j < L; ++j) {
        const double l = ei * dp[j];
        double d = (ai - mu[j]) - l * ei;
        d = std::fabs(d) < floor ? (d < 0 ? -floor : floor) : d;
        di[j] = 1 / d;
        xi[j] = xi[j] * sc[j] - l * xp[j];
      }
    }
    // backward: D z = y, Lᵀ x = z; ‖x‖² and xᵀTx (row i+1 once rows i and i+2 are known)
    std::fill(s2.begin(), s2.end(), 0.0);
    std::fill(xtx.begin(), xtx.end(), 0.0);
    for (std::size_t j = 0; j < L; ++j) {
      double& v = x[(n - 1) * L + j];
      v *= inv_d[(n - 1) * L + j];
      s2[j] += v * v;
    }
    for (std::size_t i = n - 1; i-- > 0;) {
      const double ei = e[i], ai1 = a[i + 1], ei1 = i + 2 < n ? e[i + 1] : 0.0;
      double* xi = &x[i * L];
      const double* xn = &x[(i + 1) * L];
      const double* xnn = i + 2 < n ? &x[(i + 2) * L] : xn;  // ei1 = 0 then
      const double* di = &inv_d[i * L];
#if defined(__GNUC__) && !defined(__clang__)  // clang warns about the GCC pragma
#pragma GCC ivdep
#endif
      for (std::size_t j = 0; j < L; ++j) {
        const double v = (xi[j] - ei * xn[j]) * di[j];
        xi[j] = v;
        s2[j] += v * v;
        xtx[j] += xn[j] * (ai1 * xn[j] + ei * v + ei1 * xnn[j]);
      }
    }
    for (std::size_t j = 0; j < L; ++j) xtx[j] += x[j] * (a[0] * x[j] + (n > 1 ? e[0] * x[L + j] : 0.0));
    // Gram–Schmidt within unresolved clusters (lanes in order; rare, so not fused).
    bool any_cluster = false;
    for (std::size_t j = 0; j < L; ++j)
      for (std::size_t k = 0; k < j; ++k) {
        const bool touching = brackets && (*brackets)[2 * j] - (*brackets)[2 * k + 1] < cluster;
        if (!touching && std::fabs(mu[j] - mu[k]) >= cluster) continue;
        any_cluster = true;
        double njk = 0, nk = 0;
        for (std::size_t i = 0; i < n; ++i) {
          njk += x[i * L + j] * x[i * L + k];
          nk += x[i * L + k] * x[i * L + k];
        }
        const double f = njk / nk;
        for (std::size_t i = 0; i < n; ++i) x[i * L + j] -= f * x[i * L + k];
      }
    // The solve's residual with respect to μ: the old vector had unit length. (After GS the
    // estimate is not valid; the exact check below still decides.)
    bool small = true;
    for (std::size_t j = 0; j < L; ++j) {
      res[j] = 1 / std::sqrt(s2[j]);
      small = small && res[j] <= target;
    }
    if (any_cluster) norms_and_quotients();
    for (std::size_t j = 0; j < L; ++j) {
      sc[j] = 1 / std::sqrt(s2[j]);
      rho[j] = xtx[j] / s2[j];
      // RQI: the Rayleigh quotient is the next shift unless it left the lane's bracket (then the
      // vector is still a mix and plain inverse iteration continues).
      if (inside(j, rho[j])) mu[j] = rho[j];
    }
    if (small) converged = true_residuals();
  }
  if (!converged) throw NumericalError("lane inverse iteration did not converge in 6 sweeps");
  // Lane-major to column-major in blocks of rows, so both sides stay in cache (a plain strided
  // copy per lane re-read the whole N × m array m times and took 40 % of the method's time).
  constexpr std::size_t block = 512;
  if (options.keep_vectors)
    for (std::size_t i0 = 0; i0 < n; i0 += block) {
      const std::size_t i1 = std::min(n, i0 + block);
      for (std::size_t j = 0; j < m; ++j) {
        double* col = z.col(static_cast<Eigen::Index>(first + j)).data();
        for (std::size_t i = i0; i < i1; ++i) col[i] = sc[j] * x[i * L + j];
      }
    }
  if (options.ipr && options.inverse_sqrt_mass) {  // Σv⁴/(Σv²)², v = w ⊙ m^{-1/2}, one row-major pass
    std::vector<double> p2(m, 0.0), p4(m, 0.0);
    const double* sm = options.inverse_sqrt_mass->data();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < m; ++j) {
        const double v = x[i * L + j] * sm[i], v2 = v * v;
        p2[j] += v2;
        p4[j] += v2 * v2;
      }
    for (std::size_t j = 0; j < m; ++j) (*options.ipr)[first + j] = p4[j] / (p2[j] * p2[j]);
  }
  for (std::size_t j = 0; j < m; ++j) {
    values[j] = rho[j];
    if (options.residual) (*options.residual)[first + j] = res[j];
  }
}

}  // namespace

Eigen::MatrixXd lane_inverse_iteration(const SymTridiagonal& t, std::vector<double>& values,
                                       const std::vector<double>* brackets, const LaneOptions& options) {
  const std::size_t n = t.size(), m = values.size();
  if (options.ipr) options.ipr->assign(m, 0.0);
  if (options.residual) options.residual->assign(m, 0.0);
  Eigen::MatrixXd z(static_cast<Eigen::Index>(n), options.keep_vectors ? static_cast<Eigen::Index>(m) : 0);
  if (m == 0) return z;
  if (m > 64) throw InvalidInput("lane_inverse_iteration", ": at most 64 lanes");
  if (options.inverse_sqrt_mass && options.inverse_sqrt_mass->size() != n)
    throw InvalidInput("lane_inverse_iteration", ": inverse_sqrt_mass must have N entries");
  const double norm = t.max_abs();
  // Lanes closer than this (or with touching brackets) are made orthogonal explicitly: their
  // shifts cannot tell them apart. Lanes farther apart converge to distinct eigenvectors inside
  // disjoint brackets, orthogonal to ~ε‖T‖/gap without help.
  const double cluster = kClusterGap * norm;
  auto touching = [&](std::size_t j, std::size_t k) {  // k < j
    return (brackets && (*brackets)[2 * j] - (*brackets)[2 * k + 1] < cluster) ||
           std::fabs(values[j] - values[k]) < cluster;
  };
  // Groups of at most options.group lanes (memory 2 N × group doubles), never splitting a cluster.
  const std::size_t g = options.group == 0 ? m : options.group;
  std::size_t j0 = 0;
  std::vector<double> group_values, group_brackets;
  while (j0 < m) {
    std::size_t j1 = std::min(m, j0 + g);
    while (j1 < m && j1 > j0 + 1 && touching(j1, j1 - 1)) --j1;  // move the cut out of a cluster
    if (j1 < m && touching(j1, j1 - 1)) {                        // a cluster longer than a group
      j1 = j0 + 1;
      while (j1 < m && touching(j1, j1 - 1)) ++j1;
    }
    group_values.assign(values.begin() + static_cast<long>(j0), values.begin() + static_cast<long>(j1));
    if (brackets)
      group_brackets.assign(brackets->begin() + 2 * static_cast<long>(j0),
                            brackets->begin() + 2 * static_cast<long>(j1));
    lane_group(t, group_values, brackets ? &group_brackets : nullptr, options, z, j0);
    std::copy(group_values.begin(), group_values.end(), values.begin() + static_cast<long>(j0));
    j0 = j1;
  }
  return z;
}

}  // namespace granular
