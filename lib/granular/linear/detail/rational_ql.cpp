#include "granular/linear/detail/rational_ql.hpp"

#include "granular/parallel/detail/vector_lanes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <type_traits>

namespace granular::detail {

namespace {

// e2[i] is negligible, the matrix splits at row i, once e2[i] ≤ ε² |d[i] d[i + 1]| (dsterf's test).
constexpr double ql_eps2 = std::numeric_limits<double>::epsilon() * std::numeric_limits<double>::epsilon();

// The control of one chain's iteration: deflation, 2×2 blocks, shifts and the iteration limit.
// The sweeps themselves are done by the caller, scalar or in a lane.
class QlControl {
 public:
  explicit QlControl(QlChain& chain)
      : chain_(&chain), d_(chain.d), e2_(chain.e2), n_(static_cast<long>(chain.n)), max_iterations_(30 * n_) {}

  /// Deflates what has converged and sets up the next sweep over [l, m]; false when the chain is
  /// finished (converged or failed, recorded in the chain). Rows [known_from, known_to) and
  /// (known_to, known_next) are known not to be negligible (the caller tested them), so the search
  /// for a split skips them.
  bool prepare(long known_from = 0, long known_to = 0, long known_next = 0) {
    while (l < n_) {
      long end = l;
      for (;; ++end) {
        if (end >= known_from && end < known_to) end = known_to;
        if (end > known_to && end < known_next) end = known_next;
        if (end + 1 >= n_ || e2_[end] <= ql_eps2 * std::fabs(d_[end] * d_[end + 1])) break;
      }
      if (end + 1 < n_) e2_[end] = 0;
      if (end == l) {
        ++l;
        continue;
      }
      if (end == l + 1) {  // a 2×2 block
        const double mean = 0.5 * (d_[l] + d_[l + 1]), half = 0.5 * (d_[l] - d_[l + 1]);
        const double radius = std::hypot(half, std::sqrt(e2_[l]));
        d_[l] = mean + radius;
        d_[l + 1] = mean - radius;
        e2_[l] = 0;
        l += 2;
        continue;
      }
      if (++iterations_ > max_iterations_) {
        chain_->converged = false;
        return false;
      }
      // Wilkinson shift from the leading 2×2 of the block [l, end]
      const double root_e = std::sqrt(e2_[l]);
      const double g = (d_[l + 1] - d_[l]) / (2 * root_e);
      sigma = d_[l] - root_e / (g + std::copysign(std::hypot(g, 1.0), g));
      m = end;
      gamma = d_[m] - sigma;
      p = gamma * gamma;
      return true;
    }
    chain_->converged = true;
    return false;
  }

  QlChain* chain_;
  double* d_;
  double* e2_;
  long n_, max_iterations_;
  long iterations_ = 0;
  // the sweep prepare() set up (it starts from c = 1, s = 0)
  long l = 0, m = 0;
  double sigma = 0, gamma = 0, p = 0;
};

// The lanes are ql_vectors native vectors of W doubles (vector_lanes.hpp).
using namespace lanes;
constexpr std::size_t ql_vectors = ql_lane_count / W;
static_assert(ql_lane_count % W == 0);

// The lanes' state: one sweep per lane, as rational_ql's locals, plus the split test of prepare()
// done on the rows as the sweep writes them: d_prev is the d[i + 2] the step before wrote (NaN at
// a sweep's first step: no test), row is i, split the lowest row i + 1 found negligible (m if
// none), next_split the one above it; left counts the steps left in the sweep (idle lanes never
// reach 0). Only ever a local whose address is not taken, so that it lives in registers.
struct QlLanes {
  V c[ql_vectors], s[ql_vectors], gamma[ql_vectors], p[ql_vectors], sigma[ql_vectors], d_prev[ql_vectors];
  M left[ql_vectors], row[ql_vectors], split[ql_vectors], next_split[ql_vectors];
};

// One lane's start of a sweep.
struct QlLaneStart {
  double gamma = 0, p = 1, sigma = 0;
  long left = std::numeric_limits<long>::max(), row = 0, split = 0;
};

// The lanes v as an array (a copy: indexing v itself would keep its owner in memory).
template <class T, class E = std::remove_cvref_t<decltype(T{}[0])>>
[[gnu::always_inline]] inline std::array<E, ql_lane_count> lane_array(const T (&v)[ql_vectors]) {
  std::array<E, ql_lane_count> out;
  for (std::size_t h = 0; h < ql_vectors; ++h) std::memcpy(out.data() + h * W, &v[h], sizeof v[h]);
  return out;
}

// Lane j of x starts the sweep `start` (c = 1, s = 0), by blends: no element is addressed.
[[gnu::always_inline]] inline void start_lane(QlLanes& x, std::size_t j, const QlLaneStart& start) {
  M lane;
  for (std::size_t w = 0; w < W; ++w) lane[w] = static_cast<long>(w);
  for (std::size_t h = 0; h < ql_vectors; ++h) {
    const M here = lane == static_cast<long>(j - h * W);
    x.c[h] = here ? V{} + 1.0 : x.c[h];
    x.s[h] = here ? V{} : x.s[h];
    x.gamma[h] = here ? V{} + start.gamma : x.gamma[h];
    x.p[h] = here ? V{} + start.p : x.p[h];
    x.sigma[h] = here ? V{} + start.sigma : x.sigma[h];
    x.d_prev[h] = here ? V{} + std::numeric_limits<double>::quiet_NaN() : x.d_prev[h];
    x.left[h] = here ? M{} + start.left : x.left[h];
    x.row[h] = here ? M{} + start.row : x.row[h];
    x.split[h] = here ? M{} + start.split : x.split[h];
    x.next_split[h] = here ? M{} + start.split : x.next_split[h];
  }
}

}  // namespace

void rational_ql(QlChain& chain) {
  chain.converged = chain.n < 2;
  if (chain.n < 2) return;
  QlControl q(chain);
  double* d = chain.d;
  double* e2 = chain.e2;
  while (q.prepare()) {
    double c = 1, s = 0, gamma = q.gamma, p = q.p;
    const double sigma = q.sigma;
    for (long i = q.m - 1; i >= q.l; --i) {
      const double bb = e2[i];
      const double r = p + bb;
      const double r_inv = 1.0 / r, p_inv = 1.0 / p;  // independent divisions
      if (i != q.m - 1) e2[i + 1] = s * r;
      const double old_c = c, old_gamma = gamma, alpha = d[i];
      c = p * r_inv;
      s = bb * r_inv;
      gamma = c * (alpha - sigma) - s * old_gamma;
      d[i + 1] = old_gamma + (alpha - gamma);
      p = p != 0 ? gamma * gamma * (r * p_inv) : old_c * bb;  // γ²/c
    }
    e2[q.l] = s * p;
    d[q.l] = sigma + gamma;
  }
}

// Each lane sweeps its own chain over its own rows, so the rows one step reads differ per lane. A
// small ring keeps the vector loop on contiguous loads and stores: the global steps go in chunks
// of `slots`; before a chunk, each lane copies the rows its steps in that chunk will read
// (row m − 1 − t at its step t) into its column of the ring, one slot per step; each step reads
// its slot and overwrites it with what it writes (d[i + 1], e2[i + 1]); after the chunk, those go
// back to the lane's chain. A lane whose sweep ends inside a chunk copies back at once, prepares
// its next sweep and stages the rest of the chunk. The ring (2 × 64 × ql_lane_count doubles,
// 16 KB) stays in L1; the copies are O(1) per step and lane, off the division chains. prepare()'s
// search for a split, O(N) per sweep, would cost as much as the sweep itself here, so the lanes
// test the rows as they write them and hand prepare() the stretches they found not negligible.
void rational_ql_lanes(std::span<QlChain> chains, QlLaneWork& work) {
  constexpr long slots = 64;
  constexpr std::size_t L = ql_lane_count;
  if (work.d.size() != slots * L) {
    work.d.assign(slots * L, 1.0);
    work.e2.assign(slots * L, 1.0);
  }
  double* ring_d = work.d.data();
  double* ring_e2 = work.e2.data();

  struct Lane {
    std::optional<QlControl> control;
    long start = 0;   // global step of the sweep's first step
    long copied = 0;  // global steps before this have been copied back
  };
  Lane lanes[L];

  // Lane j's rows for its global steps [from, to) into the ring, and its results back; both ranges
  // lie inside one chunk, so slot = step mod slots runs without wrapping.
  auto stage = [&](std::size_t j, long from, long to) {
    if (from >= to) return;
    const QlControl& q = *lanes[j].control;
    const long i = q.m - 1 - (from - lanes[j].start);
    const double* d = q.d_ + i;
    const double* e2 = q.e2_ + i;
    const std::size_t k = static_cast<std::size_t>(from % slots) * L + j;
    double* ring_dk = ring_d + k;
    double* ring_e2k = ring_e2 + k;
    for (long t = 0; t < to - from; ++t) {
      ring_dk[static_cast<std::size_t>(t) * L] = d[-t];
      ring_e2k[static_cast<std::size_t>(t) * L] = e2[-t];
    }
  };
  auto copy_back = [&](std::size_t j, long to) {
    const long from = lanes[j].copied;
    lanes[j].copied = to;
    if (from >= to) return;
    const QlControl& q = *lanes[j].control;
    const long i = q.m - 1 - (from - lanes[j].start);
    double* d = q.d_ + i + 1;
    double* e2 = q.e2_ + i + 1;
    const std::size_t k = static_cast<std::size_t>(from % slots) * L + j;
    const double* ring_dk = ring_d + k;
    const double* ring_e2k = ring_e2 + k;
    d[0] = ring_dk[0];
    if (i != q.m - 1) e2[0] = ring_e2k[0];  // the sweep's first step writes no e2
    for (long t = 1; t < to - from; ++t) {
      d[-t] = ring_dk[static_cast<std::size_t>(t) * L];
      e2[-t] = ring_e2k[static_cast<std::size_t>(t) * L];
    }
  };

  std::size_t next = 0, active = 0;
  // Lane j's next sweep (of its chain, or of the next chain in `chains`) from global step `step`,
  // staged up to `chunk_end`; an idle start when no chain is left.
  auto begin_sweep = [&](std::size_t j, long step, long chunk_end, long known_from, long known_to,
                         long known_next) -> QlLaneStart {
    for (;;) {
      std::optional<QlControl>& q = lanes[j].control;
      if (q && q->prepare(known_from, known_to, known_next)) {
        const long length = q->m - q->l;
        lanes[j].start = lanes[j].copied = step;
        stage(j, step, std::min(step + length, chunk_end));
        return {q->gamma, q->p, q->sigma, length, q->m - 1, q->m};
      }
      if (q) {
        q.reset();
        --active;
      }
      while (next < chains.size() && chains[next].n < 2) chains[next++].converged = true;
      if (next == chains.size()) return {};  // idle: harmless values, never finishing
      q.emplace(chains[next++]);
      ++active;
      known_from = known_to = known_next = 0;
    }
  };
  // Lane j's sweep ended with global step `last`, leaving s, p, σ, γ: its results back into its chain.
  auto end_sweep = [&](std::size_t j, long last, double s, double p, double sigma, double gamma) {
    copy_back(j, last + 1);
    const QlControl& q = *lanes[j].control;
    q.e2_[q.l] = s * p;
    q.d_[q.l] = sigma + gamma;
  };

  QlLanes x{};  // the lanes' state
  for (std::size_t j = 0; j < L; ++j) start_lane(x, j, begin_sweep(j, 0, slots, 0, 0, 0));
  for (long chunk_start = 0; active > 0; chunk_start += slots) {
    const long chunk_end = chunk_start + slots;
    for (long step = chunk_start; step < chunk_end && active > 0; ++step) {
      double* row_d = ring_d + static_cast<std::size_t>(step - chunk_start) * L;
      double* row_e2 = ring_e2 + static_cast<std::size_t>(step - chunk_start) * L;
      M ended = M{};
      for (std::size_t h = 0; h < ql_vectors; ++h) {
        const V bb = load(row_e2 + h * W), alpha = load(row_d + h * W);
        const V r = x.p[h] + bb;
        const V r_inv = 1.0 / r, p_inv = 1.0 / x.p[h];  // independent divisions
        const V e2_new = x.s[h] * r;
        store(row_e2 + h * W, e2_new);
        const V old_c = x.c[h], old_gamma = x.gamma[h];
        x.c[h] = x.p[h] * r_inv;
        x.s[h] = bb * r_inv;
        x.gamma[h] = x.c[h] * (alpha - x.sigma[h]) - x.s[h] * old_gamma;
        const V d_new = old_gamma + (alpha - x.gamma[h]);
        store(row_d + h * W, d_new);
        const M negligible = e2_new <= ql_eps2 * vabs(d_new * x.d_prev[h]);
        x.next_split[h] = negligible ? x.split[h] : x.next_split[h];
        x.split[h] = negligible ? x.row[h] + 1 : x.split[h];
        x.d_prev[h] = d_new;
        x.row[h] -= 1;
        const V rational = x.gamma[h] * x.gamma[h] * (r * p_inv), zero_p = old_c * bb;  // γ²/c
        x.p[h] = x.p[h] != 0.0 ? rational : zero_p;
        x.left[h] -= 1;
        ended |= x.left[h] == 0;
      }
      long any_ended = 0;
      for (std::size_t w = 0; w < W; ++w) any_ended |= ended[w];
      if (any_ended == 0) continue;
      // the lanes whose sweep ended, read once: start_lane changes only the lane it starts
      const auto left = lane_array(x.left), split = lane_array(x.split), next_split = lane_array(x.next_split);
      const auto s = lane_array(x.s), p = lane_array(x.p), sigma = lane_array(x.sigma), gamma = lane_array(x.gamma);
      for (std::size_t j = 0; j < L; ++j)
        if (left[j] == 0) {
          end_sweep(j, step, s[j], p[j], sigma[j], gamma[j]);
          start_lane(x, j, begin_sweep(j, step + 1, chunk_end, lanes[j].control->l + 1, split[j], next_split[j]));
        }
    }
    for (std::size_t j = 0; j < L; ++j)
      if (lanes[j].control) {
        copy_back(j, chunk_end);
        stage(j, chunk_end, std::min(lanes[j].start + (lanes[j].control->m - lanes[j].control->l), chunk_end + slots));
      }
  }
}

}  // namespace granular::detail
