#include "granular/linear/detail/partial_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <string>

#include <Eigen/Core>

#include "granular/error.hpp"
#include "granular/linear/detail/lapack_eigensolver.hpp"
#include "granular/linear/detail/localized_modes.hpp"
#include "granular/linear/detail/mode_vector.hpp"
#include "granular/linear/detail/shift_invert_eigensolvers.hpp"
#include "granular/linear/detail/sturm_bisection.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_ipr.hpp"
#include "granular/linear/tridiagonal_operator.hpp"

namespace granular {

namespace {

/// Eigenpairs computed by a method, a contiguous run of the spectrum, ascending.
struct Candidates {
  std::vector<double> values;
  Eigen::MatrixXd vectors;  // N × values.size()
  long first_mode = -1;     // mode number of values[0] when the method knows it (LAPACK), else -1
  std::string method;
  int restarts = 0;
  std::vector<double> ipr, residual;  // precomputed per candidate (bisect lanes), else empty
};

/// The test seam of detail/partial_spectrum.hpp: drops one candidate when asked to.
void apply_test_seam(Candidates& c) {
  if (!detail::hide_candidate) return;
  const std::size_t m = c.values.size();
  const std::size_t drop = detail::hide_candidate(c.method, c.values);
  if (drop >= m) return;
  c.values.erase(c.values.begin() + static_cast<long>(drop));
  if (c.vectors.cols() == static_cast<Eigen::Index>(m)) {
    Eigen::MatrixXd kept(c.vectors.rows(), static_cast<Eigen::Index>(m - 1));
    for (std::size_t j = 0, k = 0; j < m; ++j)
      if (j != drop) kept.col(static_cast<Eigen::Index>(k++)) = c.vectors.col(static_cast<Eigen::Index>(j));
    c.vectors = std::move(kept);
  }
  if (c.ipr.size() == m) c.ipr.erase(c.ipr.begin() + static_cast<long>(drop));
  if (c.residual.size() == m) c.residual.erase(c.residual.begin() + static_cast<long>(drop));
}

/// Mode number of the first of a contiguous run of eigenvalues: an inertia count in the widest gap
/// of the run, so that round-off in the count cannot hit an eigenvalue.
long first_mode_number(const TridiagonalOperator& op, const std::vector<double>& v, double scale) {
  if (v.size() == 1)
    return static_cast<long>(op.count_below(v[0] - 64 * std::numeric_limits<double>::epsilon() * scale)) + 1;
  std::size_t widest = 0;
  for (std::size_t i = 1; i + 1 < v.size(); ++i)
    if (v[i + 1] - v[i] > v[widest + 1] - v[widest]) widest = i;
  const double p = 0.5 * (v[widest] + v[widest + 1]);
  return static_cast<long>(op.count_below(p)) - static_cast<long>(widest);
}

/// Indices into `values` (ascending) of the `count` nearest f0 in frequency, ascending. Ties: lower first.
std::vector<std::size_t> nearest_in_frequency(const std::vector<double>& values, double f0, std::size_t count) {
  std::vector<std::size_t> idx(values.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    return std::fabs(frequency_khz(values[a]) - f0) < std::fabs(frequency_khz(values[b]) - f0);
  });
  idx.resize(std::min(count, idx.size()));
  std::sort(idx.begin(), idx.end());
  return idx;
}

/// bisect: an eigenvalue alone in its bracket (and 2 widths from its neighbours') is bisected only
/// to this relative width; the Rayleigh-quotient iteration inside its bracket finishes it.
/// Clustered ones go to 1e-14. (1e-7 cost 4 more sweeps at N = 1e6 for the same results.)
constexpr double kIsolated = 1e-5;

/// bisect: unit eigenvectors of modes first..last (1-based) and their eigenvalues. Up to 64 modes:
/// isolated eigenvalues bisected to kIsolated, then lane (Rayleigh-quotient) inverse iteration;
/// more modes, or lanes that do not converge: full-precision bisection and one-by-one inverse
/// iteration. `values`/`brackets`, when given (non-empty), are that bisection already done.
Eigen::MatrixXd bisect_pairs(const SymTridiagonal& t, long first, long last, std::vector<double>& values,
                             std::vector<double> brackets, const std::vector<double>& inverse_sqrt_mass, bool keep,
                             std::vector<double>& ipr, std::vector<double>& residual, std::size_t group) {
  const int f = static_cast<int>(first), l = static_cast<int>(last);
  ipr.clear();
  residual.clear();
  if (last - first + 1 <= 64) {
    if (brackets.empty()) values = bisect_eigenvalues(t, f, l, 1e-14, kIsolated, &brackets);
    const std::size_t n = t.size(), m = values.size();
    // Localized modes on windows of the chain first; the rest (extended, clustered) in the whole chain.
    Eigen::MatrixXd z(static_cast<Eigen::Index>(n), keep ? static_cast<Eigen::Index>(m) : 0);
    LocalizedModes local = solve_localized_modes(t, values, brackets, inverse_sqrt_mass, keep ? &z : nullptr);
    std::vector<std::size_t> rest;
    std::vector<double> rest_values, rest_brackets;
    for (std::size_t j = 0; j < m; ++j)
      if (!local.solved[j]) {
        rest.push_back(j);
        rest_values.push_back(values[j]);
        rest_brackets.push_back(brackets[2 * j]);
        rest_brackets.push_back(brackets[2 * j + 1]);
      }
    LaneOptions lanes;
    lanes.keep_vectors = keep;  // IPRs and residuals come from the lanes: no N × K copy needed
    lanes.group = group;
    lanes.inverse_sqrt_mass = &inverse_sqrt_mass;
    lanes.ipr = &ipr;
    lanes.residual = &residual;
    try {
      const Eigen::MatrixXd zr =
          rest.empty() ? Eigen::MatrixXd{} : lane_inverse_iteration(t, rest_values, &rest_brackets, lanes);
      for (std::size_t q = 0; q < rest.size(); ++q) {
        const std::size_t j = rest[q];
        local.values[j] = rest_values[q];
        local.ipr[j] = ipr[q];
        local.residual[j] = residual[q];
        if (keep) z.col(static_cast<Eigen::Index>(j)) = zr.col(static_cast<Eigen::Index>(q));
      }
      values = std::move(local.values);
      ipr = std::move(local.ipr);
      residual = std::move(local.residual);
      return z;
    } catch (const NumericalError&) {
      ipr.clear();
      residual.clear();
    }
  }
  values = bisect_eigenvalues(t, f, l, 1e-14);
  return inverse_iteration(t, values);
}

/// Eigenpairs first..last (1-based) by dstemr (lapack) or bisection + inverse iteration (bisect).
Candidates by_index(SpectrumMethod method, const SymTridiagonal& t, long first, long last,
                    const std::vector<double>& inverse_sqrt_mass, bool keep, std::size_t group) {
  Candidates out;
  out.first_mode = first;
  if (method == SpectrumMethod::lapack) {
    LapackEigensolver solver;
    EigenDecomposition eig;
    solver.solve_indices(t, static_cast<int>(first), static_cast<int>(last), true, eig);
    out.values.assign(eig.values.data(), eig.values.data() + eig.values.size());
    out.vectors = std::move(eig.vectors);
    out.method = "lapack-" + std::string(to_string(eig.driver));
  } else {
    out.vectors = bisect_pairs(t, first, last, out.values, {}, inverse_sqrt_mass, keep, out.ipr, out.residual, group);
    out.method = "bisect";
  }
  apply_test_seam(out);
  return out;
}

Candidates shift_invert(SpectrumMethod method, const SymTridiagonal& t, double sigma, int count,
                        const SpectrumConfig& config) {
  ShiftInvertConfig c;
  c.count = count;
  c.tolerance = config.tolerance;
  c.subspace = config.subspace;
  ShiftInvertResult r = method == SpectrumMethod::arpack ? arpack_nearest(t, sigma, c) : slepc_nearest(t, sigma, c);
  Candidates out;
  out.values = std::move(r.values);
  out.vectors = std::move(r.vectors);
  out.method = std::string(to_string(method));
  out.restarts = r.restarts;
  apply_test_seam(out);
  return out;
}

/// One attempt by config.method, unchecked.
Spectrum solve_partial(const SymTridiagonal& t, const std::vector<double>& inverse_sqrt_mass,
                       const ModeSelection& selection, const SpectrumConfig& config, const TridiagonalOperator& op,
                       double scale) {
  const std::size_t n = t.size();

  Candidates cand;
  std::vector<std::size_t> chosen;  // indices into cand.values
  if (selection.kind == ModeSelection::Kind::window) {
    const double lo = omega_squared_of_khz(selection.lo_khz), hi = omega_squared_of_khz(selection.hi_khz);
    const std::size_t below = op.count_below(lo);
    const std::size_t upto = op.count_below(std::nextafter(hi, std::numeric_limits<double>::infinity()));
    if (upto > below) {
      if (config.method == SpectrumMethod::lapack || config.method == SpectrumMethod::bisect) {
        cand = by_index(config.method, t, static_cast<long>(below) + 1, static_cast<long>(upto), inverse_sqrt_mass,
                        config.vectors, config.lanes);
      } else {
        // The window is symmetric about its centre in ω², so its modes are the (upto − below)
        // eigenvalues nearest the centre.
        cand = shift_invert(config.method, t, 0.5 * (lo + hi), static_cast<int>(upto - below), config);
      }
      cand.first_mode = static_cast<long>(below) + 1;
      chosen.resize(cand.values.size());
      std::iota(chosen.begin(), chosen.end(), 0);
    } else {
      cand.method = config.method == SpectrumMethod::lapack ? "lapack-stemr" : std::string(to_string(config.method));
    }
  } else {
    const double f0 = selection.near_khz;
    const auto k = static_cast<std::size_t>(selection.count);
    const double sigma = omega_squared_of_khz(f0);
    if (config.method == SpectrumMethod::lapack || config.method == SpectrumMethod::bisect) {
      // The K nearest form a run of consecutive modes that contains mode c or c + 1 (c = modes
      // below σ); one extra on each side absorbs a count off by one in round-off.
      const long c = static_cast<long>(op.count_below(sigma));
      const long first = std::max(1L, c - static_cast<long>(k)),
                 last = std::min(static_cast<long>(n), c + static_cast<long>(k) + 1);
      if (config.method == SpectrumMethod::lapack) {
        cand = by_index(config.method, t, first, last, inverse_sqrt_mass, config.vectors, config.lanes);
        chosen = nearest_in_frequency(cand.values, f0, k);
      } else {
        // Values first (coarse where isolated), then vectors for the K chosen plus one on each
        // side, then the final choice on the refined values (a coarse ranking could swap two
        // nearly equidistant modes).
        const bool coarse = last - first + 1 <= 64;
        std::vector<double> brackets;
        const auto values = bisect_eigenvalues(t, static_cast<int>(first), static_cast<int>(last), 1e-14,
                                               coarse ? kIsolated : 0, &brackets, sigma, k);
        const auto pick = nearest_in_frequency(values, f0, k);
        const long a = std::max(first, first + static_cast<long>(pick.front()) - 1);
        const long b = std::min(last, first + static_cast<long>(pick.back()) + 1);
        cand.values.assign(values.begin() + (a - first), values.begin() + (b - first) + 1);
        std::vector<double> sub(brackets.begin() + 2 * (a - first), brackets.begin() + 2 * (b - first) + 2);
        cand.vectors = bisect_pairs(t, a, b, cand.values, b - a + 1 <= 64 ? std::move(sub) : std::vector<double>{},
                                    inverse_sqrt_mass, config.vectors, cand.ipr, cand.residual, config.lanes);
        cand.first_mode = a;
        cand.method = "bisect";
        apply_test_seam(cand);
        chosen = nearest_in_frequency(cand.values, f0, k);
      }
    } else {
      if (k > n - 1)
        throw InvalidInput("count", " " + std::to_string(k) + ": method " + std::string(to_string(config.method)) +
                                        " needs K <= N - 1 = " + std::to_string(n - 1) + " (use method lapack)");
      // Shift-invert converges fast only when the wanted eigenvalues are the nearest to the shift
      // *and* spread out compared with their distance from it. Inside a band (≥ 2K modes within
      // ±0.1 % of f0) σ itself is a good shift. In a gap, or beyond the spectrum, the K nearest sit
      // far away in a tight bunch (RDM2 at 15 kHz: ARPACK needed 340 s at N = 1e4); there the K
      // nearest are first located by a coarse many-shift bisection and the shift goes to their centre.
      const bool in_band = f0 > 0 && op.count_below(omega_squared_of_khz(f0 * (1 + 1e-3))) -
                                             op.count_below(omega_squared_of_khz(f0 * (1 - 1e-3))) >=
                                         2 * k;
      const auto [glo, ghi] = op.spectrum_bounds();
      const double s = std::clamp(sigma, glo, ghi);
      std::size_t extra = std::max<std::size_t>(2, k / 5);
      if (!in_band) {
        const long c = static_cast<long>(op.count_below(sigma));
        const long first = std::max(1L, c - static_cast<long>(k));
        const long last = std::min(static_cast<long>(n), c + static_cast<long>(k) + 1);
        const auto values = bisect_eigenvalues(t, static_cast<int>(first), static_cast<int>(last), 1e-9);
        const auto pick = nearest_in_frequency(values, f0, k);
        const double centre = 0.5 * (values[pick.front()] + values[pick.back()]);
        cand = shift_invert(config.method, t, centre, static_cast<int>(k), config);
        cand.first_mode = first + static_cast<long>(pick.front());
        // Modes other than the located ones (or a missed one) fail the node-count check below.
        if (cand.values.size() != k)
          throw NumericalError("near_khz: " + std::string(to_string(config.method)) + " returned " +
                               std::to_string(cand.values.size()) + " of " + std::to_string(k) + " modes");
        chosen.resize(k);
        std::iota(chosen.begin(), chosen.end(), 0);
      }
      // Shift-invert finds the nearest in ω², not in f. Ask for a few more and accept once the
      // K-th nearest in f lies strictly inside the ω² interval the candidates are known to cover.
      while (in_band) {
        const std::size_t want = std::min(k + extra, n - 1);
        if (want < k)
          throw InvalidInput("count", " " + std::to_string(k) + ": method " + std::string(to_string(config.method)) +
                                          " needs K <= N - 1 = " + std::to_string(n - 1) + " (use method lapack)");
        cand = shift_invert(config.method, t, s, static_cast<int>(want), config);
        double r = 0;
        for (double v : cand.values) r = std::max(r, std::fabs(v - s));
        const double inf = std::numeric_limits<double>::infinity();
        const double reach_down = s - r < glo ? inf : f0 - frequency_khz(s - r);
        const double reach_up = s + r > ghi ? inf : frequency_khz(s + r) - f0;
        chosen = nearest_in_frequency(cand.values, f0, k);
        double dk = 0;
        for (std::size_t i : chosen) dk = std::max(dk, std::fabs(frequency_khz(cand.values[i]) - f0));
        if (dk < std::min(reach_down, reach_up) || want == n - 1) {
          if (dk < std::min(reach_down, reach_up)) break;
          throw NumericalError("near_khz: cannot certify the " + std::to_string(k) + " nearest modes with " +
                               std::string(to_string(config.method)) + " (use method lapack)");
        }
        extra *= 2;
      }
    }
  }

  Spectrum out;
  out.beads = n;
  out.info.method = cand.method;
  out.info.restarts = cand.restarts;
  out.info.candidates = static_cast<int>(cand.values.size());
  if (chosen.empty()) return out;
  const long first = cand.first_mode > 0 ? cand.first_mode : first_mode_number(op, cand.values, scale);
  const std::size_t m = chosen.size();
  out.mode.resize(m);
  out.omega2.resize(m);
  out.freq_khz.resize(m);
  out.ipr.resize(m);
  out.residual.resize(m);
  if (config.vectors) out.vectors.resize(n * m);  // column-major: mode j at [j·N, (j+1)·N)
  std::vector<double> tw(n);
  const bool precomputed = !cand.ipr.empty();
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t i = chosen[j];
    out.mode[j] = static_cast<std::size_t>(first + static_cast<long>(i));
    out.omega2[j] = cand.values[i];
    out.freq_khz[j] = frequency_khz(cand.values[i]);
    if (precomputed) {
      out.ipr[j] = cand.ipr[i];
      out.residual[j] = cand.residual[i] / scale;
    }
    if (precomputed && !config.vectors) continue;
    double* w = cand.vectors.col(static_cast<Eigen::Index>(i)).data();
    detail::normalize_mode(w, n);
    if (!precomputed) {
      const double lambda = cand.values[i];
      t.multiply(w, tw.data());
      double r2 = 0;
      for (std::size_t q = 0; q < n; ++q) {
        const double d = tw[q] - lambda * w[q];
        r2 += d * d;
      }
      out.ipr[j] = displacement_ipr(w, inverse_sqrt_mass.data(), n);
      out.residual[j] = std::sqrt(r2) / scale;
    }
    if (config.vectors) std::copy(w, w + n, out.vectors.data() + j * n);
  }
  return out;
}

/// The node-count check. Every returned eigenvalue is within δ = max(64ε,
/// 2·residual)·‖T‖ of a true one (Weyl), so the inertia count N(σ) decides, for points more than
/// δ from every returned value, how many true eigenvalues the result should hold:
///   - the result must be contiguous: N(v_max − δ) − N(v_min + δ) equals the returned values in
///     [v_min + δ, v_max − δ), and each end zone [v ± δ] holds at least the returned values in it;
///   - its numbering must match: mode(v_min) ∈ (N(v_min − δ), N(v_min + δ)];
///   - window: exactly the count N(hi⁺) − N(lo) of modes, each inside [lo − δ, hi + δ];
///   - nearest: no eigenvalue left out nearer to f0 than the farthest returned one: the true
///     eigenvalues strictly (by δ) inside the frequency ball of the farthest returned mode are
///     exactly the returned ones there.
/// Returns an empty string when the result passes, else what failed.
std::string node_count_check(const Spectrum& p, const ModeSelection& selection, const TridiagonalOperator& op,
                             double scale) {
  const std::size_t m = p.size();
  auto in = [&](double a, double b) {  // returned values in [a, b)
    return static_cast<std::size_t>(
        std::count_if(p.omega2.begin(), p.omega2.end(), [&](double v) { return v >= a && v < b; }));
  };
  double rmax = 0;
  for (double r : p.residual) rmax = std::max(rmax, r);
  const double delta = std::max(64 * std::numeric_limits<double>::epsilon(), 2 * rmax) * scale;
  const double inf = std::numeric_limits<double>::infinity();
  // Every inertia count the check needs, in one many-shift sweep (one count per O(N) sweep was
  // ~10 sweeps at N = 1e6); its pivots are op.count_below's (an AVX-512 build divides by a refined reciprocal).
  double lo = 0, hi_up = 0, a_near = -inf, b_near = 0;
  std::vector<double> points;
  if (selection.kind == ModeSelection::Kind::window) {
    lo = omega_squared_of_khz(selection.lo_khz);
    hi_up = std::nextafter(omega_squared_of_khz(selection.hi_khz), inf);
    points = {lo, hi_up};
  }
  if (m > 0) {
    const double vmin = p.omega2.front(), vmax = p.omega2.back();
    for (double x : {vmin - delta, vmin + delta, vmax - delta, vmax + delta}) points.push_back(x);
    if (selection.kind == ModeSelection::Kind::nearest) {
      const double f0 = selection.near_khz;
      double dk = 0;
      for (double f : p.freq_khz) dk = std::max(dk, std::fabs(f - f0));
      a_near = f0 > dk ? omega_squared_of_khz(f0 - dk) + delta : -inf;
      b_near = omega_squared_of_khz(f0 + dk) - delta;
      if (std::isfinite(a_near)) points.push_back(a_near);
      points.push_back(b_near);
    }
  }
  const std::vector<long> counted = points.empty() ? std::vector<long>{} : count_below_many(op.matrix(), points);
  auto below = [&](double x) {
    const auto at = std::find(points.begin(), points.end(), x);
    return at == points.end() ? op.count_below(x) : static_cast<std::size_t>(counted[at - points.begin()]);
  };
  auto count = [&](double a, double b) { return b > a ? below(b) - below(a) : std::size_t{0}; };
  if (selection.kind == ModeSelection::Kind::window) {
    const double hi = omega_squared_of_khz(selection.hi_khz);
    const std::size_t expect = below(hi_up) - below(lo);
    if (m != expect)
      return "the window holds " + std::to_string(expect) + " eigenvalues by node count, " + std::to_string(m) +
             " returned";
    for (double v : p.omega2)
      if (v < lo - delta || v > hi + delta) return "a returned eigenvalue lies outside the window";
  }
  if (m == 0) return {};
  for (std::size_t j = 1; j < m; ++j)
    // Inside an exactly degenerate cluster (mirror-symmetric chains) refined eigenvalues may come
    // back reversed by an ulp: order within the eigenvalues' precision δ is all that is defined.
    if (p.mode[j] != p.mode[j - 1] + 1 || p.omega2[j] < p.omega2[j - 1] - delta)
      return "the returned modes are not consecutive";
  const double vmin = p.omega2.front(), vmax = p.omega2.back();
  const std::size_t below_lo = below(vmin - delta), above_lo = below(vmin + delta);
  if (!(p.mode.front() > below_lo && p.mode.front() <= above_lo))
    return "mode " + std::to_string(p.mode.front()) + " is numbered " + std::to_string(below_lo + 1) + ".." +
           std::to_string(above_lo) + " by node count";
  // Returned values sit within δ/2 of their true eigenvalues: near a boundary either may fall on
  // either side, so the true count must lie between the returned counts of the interval shrunk
  // and widened by δ/2 (a missed eigenvalue makes it exceed the widened count).
  auto agrees = [&](double a, double b) {
    const std::size_t truth = count(a, b);
    return truth >= in(a + 0.5 * delta, b - 0.5 * delta) && truth <= in(a - 0.5 * delta, b + 0.5 * delta);
  };
  if (vmax - vmin > 2 * delta) {
    if (!agrees(vmin + delta, vmax - delta))
      return "an eigenvalue inside the returned range was missed (node count " +
             std::to_string(count(vmin + delta, vmax - delta)) + ", returned " +
             std::to_string(in(vmin + delta, vmax - delta)) + ")";
    if (count(vmin - delta, vmin + delta) < in(vmin - delta, vmin + delta) ||
        count(vmax - delta, vmax + delta) < in(vmax - delta, vmax + delta))
      return "more eigenvalues returned at an end than exist there";
  }
  if (selection.kind == ModeSelection::Kind::nearest) {
    const double a = a_near, b = b_near;
    const std::size_t truth = b > a ? below(b) - (std::isfinite(a) ? below(a) : 0) : 0;
    if (b > a && !(truth >= in(a + 0.5 * delta, b - 0.5 * delta) && truth <= in(a - 0.5 * delta, b + 0.5 * delta)))
      return "an eigenvalue nearer to near_khz than the farthest returned mode was left out (node count " +
             std::to_string(truth) + ", returned " + std::to_string(in(a, b)) + ")";
  }
  return {};
}

}  // namespace

namespace detail {
CandidateSeam hide_candidate = nullptr;
}  // namespace detail

Spectrum partial_spectrum(const SymTridiagonal& t, const std::vector<double>& inverse_sqrt_mass,
                          const ModeSelection& selection, const SpectrumConfig& config) {
  const std::size_t n = t.size();
  if (n < 2) throw InvalidInput("N", " " + std::to_string(n) + ": a chain needs at least 2 beads");
  if (inverse_sqrt_mass.size() != n)
    throw InvalidInput("inverse_sqrt_mass", ": must have N = " + std::to_string(n) + " entries");
  validate(selection, n);
  const TridiagonalOperator op(t);
  const double scale = t.max_abs();
  if (!std::isfinite(scale) || !(scale > 0)) throw NumericalError("dynamical matrix has a non-finite or zero scale");
  std::string failure;
  try {
    Spectrum out = solve_partial(t, inverse_sqrt_mass, selection, config, op, scale);
    failure = node_count_check(out, selection, op, scale);
    if (failure.empty()) return out;
    failure = out.info.method + ": " + failure;
  } catch (const NumericalError& e) {
    if (config.method == SpectrumMethod::bisect) throw;
    failure = e.what();
  }
  // Recovery: bisection numbers its modes by the same inertia count, so it cannot skip one.
  SpectrumConfig again = config;
  again.method = SpectrumMethod::bisect;
  if (config.method == SpectrumMethod::bisect)
    throw NumericalError("partial spectrum failed the node-count check: " + failure);
  Spectrum out = solve_partial(t, inverse_sqrt_mass, selection, again, op, scale);
  const std::string second = node_count_check(out, selection, op, scale);
  if (!second.empty())
    throw NumericalError("partial spectrum failed the node-count check: " + failure + "; bisect fallback: " + second);
  out.info.method = std::string(to_string(config.method)) + "→" + out.info.method;
  out.info.fallbacks = 1;
  return out;
}

}  // namespace granular
