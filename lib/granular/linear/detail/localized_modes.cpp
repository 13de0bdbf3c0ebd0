#include "granular/linear/detail/localized_modes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "granular/error.hpp"
#include "granular/linear/detail/sturm_bisection.hpp"
#include "granular/linear/detail/sturm_count.hpp"

namespace granular {

namespace {

/// The first window (rows), and the largest before a mode is left to the whole-chain solve: ×4
/// per try, so a mode that no window holds costs ~1.3 × the largest window, not O(N) per try.
constexpr std::size_t kFirstWindow = 2048, kLastWindow = 32768;

/// Anchors of up to 4 G modes in one sweep: lanes of lo ends and of hi ends side by side; the
/// prefix counts are the Sturm recurrence of detail/sturm_count.hpp, so at the last row they are
/// the whole chain's counts.
template <int G>
void anchor_sweep(const SymTridiagonal& t, double pivmin, const double* lo, const double* hi, std::size_t* anchor) {
#if defined(__GNUC__)
  using v4 = detail::SturmLanes;
  using m4 = detail::SturmMasks;
#else
#error "mode_anchors needs GCC/Clang vector extensions"
#endif
  const std::size_t n = t.size();
  const double* a = t.diagonal.data();
  const double* b = t.off_diagonal.data();
  const v4 zero{}, pm = zero + pivmin;
  auto guard = [&](v4 q) { return detail::sturm_guard(q, pm); };
  v4 slo[G], shi[G], plo[G], phi[G];
  m4 clo[G], chi[G], inside[G], last[G];
  for (int g = 0; g < G; ++g) {
    for (int k = 0; k < 4; ++k) {
      slo[g][k] = lo[4 * g + k];
      shi[g][k] = hi[4 * g + k];
    }
    plo[g] = guard((zero + a[0]) - slo[g]);
    phi[g] = guard((zero + a[0]) - shi[g]);
    clo[g] = -(plo[g] < zero);
    chi[g] = -(phi[g] < zero);
    inside[g] = chi[g] > clo[g];
    last[g] = m4{} + 0;
  }
  for (std::size_t i = 1; i < n; ++i) {
    const v4 ai = zero + a[i], b2 = zero + b[i - 1] * b[i - 1];
    const m4 row = m4{} + static_cast<long long>(i);
    for (int g = 0; g < G; ++g) {
      plo[g] = guard((ai - slo[g]) - b2 / plo[g]);
      phi[g] = guard((ai - shi[g]) - b2 / phi[g]);
      clo[g] -= plo[g] < zero;
      chi[g] -= phi[g] < zero;
      const m4 now = chi[g] > clo[g];
      last[g] = (now & ~inside[g]) ? row : last[g];
      inside[g] = now;
    }
  }
  for (int g = 0; g < G; ++g)
    for (int k = 0; k < 4; ++k) anchor[4 * g + k] = static_cast<std::size_t>(last[g][k]);
}

}  // namespace

std::vector<std::size_t> mode_anchors(const SymTridiagonal& t, const std::vector<double>& brackets) {
  const std::size_t m = brackets.size() / 2;
  std::vector<std::size_t> anchor(m, 0);
  if (t.size() == 0) return anchor;
  const double pivmin = detail::sturm_pivot_floor(t);
  constexpr int G = 2;  // 8 modes, 16 lanes, 4 division chains per sweep: enough to hide the divider's latency
  for (std::size_t j0 = 0; j0 < m; j0 += 4 * G) {
    double lo[4 * G], hi[4 * G];
    std::size_t got[4 * G];
    const std::size_t k = std::min<std::size_t>(4 * G, m - j0);
    for (std::size_t j = 0; j < 4 * G; ++j) {  // pad with a repeat
      lo[j] = brackets[2 * (j0 + std::min(j, k - 1))];
      hi[j] = brackets[2 * (j0 + std::min(j, k - 1)) + 1];
    }
    anchor_sweep<G>(t, pivmin, lo, hi, got);
    std::copy(got, got + k, anchor.begin() + static_cast<long>(j0));
  }
  return anchor;
}

LocalizedModes solve_localized_modes(const SymTridiagonal& t, const std::vector<double>& values,
                                     const std::vector<double>& brackets, const std::vector<double>& inverse_sqrt_mass,
                                     Eigen::MatrixXd* vectors) {
  const std::size_t n = t.size(), m = values.size();
  LocalizedModes out{values, std::vector<double>(m, 0.0), std::vector<double>(m, 0.0), std::vector<bool>(m, false)};
  if (m == 0 || n < 4 * kFirstWindow || brackets.size() != 2 * m || inverse_sqrt_mass.size() != n) return out;
  const double norm = t.max_abs();
  // The whole-chain solve's targets (lane_inverse_iteration): residual (also the bracket slack), clusters.
  const double target = kResidualTarget * norm, slack = target, cluster = kClusterGap * norm;
  auto isolated = [&](std::size_t j) {
    const bool below = j > 0 && brackets[2 * j] - brackets[2 * j - 1] < cluster;
    const bool above = j + 1 < m && brackets[2 * j + 2] - brackets[2 * j + 1] < cluster;
    return !below && !above;
  };
  const std::vector<std::size_t> anchor = mode_anchors(t, brackets);
  const double* a = t.diagonal.data();
  const double* b = t.off_diagonal.data();
  SymTridiagonal sub;
  std::vector<double> sub_mass, value(1), bracket(2), ipr, residual;
  for (std::size_t j = 0; j < m; ++j) {
    if (!isolated(j)) continue;
    const double lo = brackets[2 * j], hi = brackets[2 * j + 1];
    for (std::size_t w = kFirstWindow; w <= kLastWindow && 4 * w <= n; w *= 4) {
      // The anchor sits right of the centre (where the right tail has decayed to ~√(bracket
      // width)); the left tail needs the longer side.
      std::size_t s = anchor[j] > 3 * w / 4 ? anchor[j] - 3 * w / 4 : 0;
      const std::size_t e = std::min(n, s + w);
      s = e - w;
      sub.diagonal.assign(a + s, a + e);
      sub.off_diagonal.assign(b + s, b + e - 1);
      sub_mass.assign(inverse_sqrt_mass.begin() + static_cast<long>(s),
                      inverse_sqrt_mass.begin() + static_cast<long>(e));
      value[0] = values[j];
      bracket[0] = lo;
      bracket[1] = hi;
      LaneOptions options;
      options.group = 1;
      options.keep_vectors = true;
      options.inverse_sqrt_mass = &sub_mass;
      options.ipr = &ipr;
      options.residual = &residual;
      Eigen::MatrixXd z;
      try {
        z = lane_inverse_iteration(sub, value, &bracket, options);
      } catch (const NumericalError&) {
        continue;  // the window cut the mode (its eigenvalue left the bracket): grow it
      }
      // The rows just outside the window see b · (edge entry): the vector's residual in the whole chain.
      const double left = s > 0 ? b[s - 1] * z(0, 0) : 0.0;
      const double right = e < n ? b[e - 1] * z(static_cast<Eigen::Index>(w - 1), 0) : 0.0;
      const double whole = std::sqrt(residual[0] * residual[0] + left * left + right * right);
      if (!(whole <= target) || value[0] < lo - slack || value[0] > hi + slack) continue;
      out.values[j] = value[0];
      out.ipr[j] = ipr[0];
      out.residual[j] = whole;
      out.solved[j] = true;
      if (vectors) {
        auto col = vectors->col(static_cast<Eigen::Index>(j));
        col.setZero();
        col.segment(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(w)) = z.col(0);
      }
      break;
    }
  }
  return out;
}

}  // namespace granular
