// The splitting scheme on W chains side by side (lane_propagator.hpp): the step sequence of
// splitting_propagator.cpp, with the lane kernels of detail/lane_kernels.hpp.
#include "granular/lanes/lane_propagator.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <tuple>
#include <variant>

#include "granular/dynamics/detail/splitting_sequence.hpp"
#include "granular/dynamics/detail/window_rule.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/error.hpp"
#include "granular/lanes/detail/lane_chains.hpp"
#include "granular/lanes/detail/lane_kernels.hpp"

namespace granular {

namespace {

namespace lk = detail::lane_kernels;
using lk::W;

lk::M as_lanes(const std::size_t* x) {
  lk::M out{};
  for (std::size_t l = 0; l < W; ++l) out[l] = static_cast<long>(x[l]);
  return out;
}

}  // namespace

std::size_t LanePropagator::width() { return W; }

LanePropagator::~LanePropagator() = default;
LanePropagator::LanePropagator(LanePropagator&&) noexcept = default;
LanePropagator& LanePropagator::operator=(LanePropagator&&) noexcept = default;

LanePropagator::LanePropagator(std::span<const ForceLaw> laws, std::span<const Chain> chains,
                               const SplittingScheme& scheme, double time_step, std::span<const State> initials,
                               const ActiveWindow& window)
    : scheme_(scheme), tau_(time_step), window_(window),
      c_(std::make_unique<detail::LaneChains>(detail::interleave(laws, chains, scheme, time_step, initials, W))),
      n_(c_->n), lanes_(c_->lanes) {
  if (window.enabled && !(window.threshold >= 0)) throw InvalidInput("active window threshold must be >= 0");
  lo_.assign(W, 0);
  hi_.assign(W, 0);  // idle lanes: an empty window, never touched
  kinetic_limit_.assign(W, 0.0);
  bond_updates_.assign(W, 0);
  for (std::size_t l = 0; l < c_->lanes; ++l) {
    std::tie(lo_[l], hi_[l]) = detail::opened_window(initials[l], window_);
    if (window_.enabled && window_.guard > 0)
      kinetic_limit_[l] = 2 * window_.threshold * total_energy(laws[l], chains[l], initials[l]);
  }
  union_lo_ = *std::min_element(lo_.begin(), lo_.begin() + static_cast<long>(c_->lanes));
  union_hi_ = *std::max_element(hi_.begin(), hi_.begin() + static_cast<long>(c_->lanes));
}

void LanePropagator::advance(std::size_t steps) {
  if (steps == 0) return;
  detail::splitting_sequence(
      scheme_, tau_, steps, [&](double h, double d) { pass(false, h, d); },
      [&](double c, double d) { pass(true, c, d); }, [&](double d) { drift(d); },
      [&] {
        if (window_.enabled) grow_windows();
      });
  steps_ += steps;
}

void LanePropagator::drift(double d) { lk::drift_only(c_->u.data(), c_->v.data(), union_lo_, union_hi_, d); }

void LanePropagator::pass(bool corrector, double weight, double d) {
  const lk::LaneLaw law{c_->p1.data(), c_->p2.data(), c_->p3.data(), c_->k.data(), c_->q.data()};
  const lk::M lo = as_lanes(lo_.data()), hi = as_lanes(hi_.data());
  detail::with_kernel(*c_, [&](auto hz, auto gr, auto qu) {
    constexpr bool hertz = decltype(hz)::value, grounded = decltype(gr)::value, quartic = decltype(qu)::value;
    if (corrector)
      lk::correct_and_drift<hertz, grounded, quartic>(law, c_->u.data(), c_->v.data(), c_->im.data(), lo, hi, union_lo_,
                                                      union_hi_, weight, d);
    else
      lk::kick_and_drift<hertz, grounded, quartic>(law, c_->u.data(), c_->v.data(), c_->im.data(), lo, hi, union_lo_,
                                                   union_hi_, weight, d);
  });
  count_updates();
}

void LanePropagator::count_updates() {
  for (std::size_t l = 0; l < c_->lanes; ++l) bond_updates_[l] += hi_[l] - lo_[l] + 1;
}

bool LanePropagator::disturbed(std::size_t lane, std::size_t begin, std::size_t end) const {
  for (std::size_t i = begin; i < end; ++i) {
    if (detail::disturbs(c_->v[i * W + lane], kinetic_limit_[lane], c_->im[i * W + lane])) return true;
  }
  return false;
}

void LanePropagator::grow_windows() {
  // SplittingPropagator::grow_window for every lane: the outermost `guard` beads on the left, the
  // window widened where one is disturbed, then on the right (from the new left edge). When the
  // lanes' edges lie close together (an ensemble kicked at one site) their rows are read once, as
  // vectors; else lane by lane.
  const std::size_t guard = window_.guard;
  std::array<std::size_t, W> begin{}, end{};  // per lane; no allocation per step
  const auto check = [&](bool left) {
    lk::M active{}, hit{};
    std::size_t first = c_->n, last = 0;
    for (std::size_t l = 0; l < c_->lanes; ++l) {
      std::tie(begin[l], end[l]) =
          left ? detail::left_edge(lo_[l], hi_[l], guard) : detail::right_edge(lo_[l], hi_[l], c_->n, guard);
      if (begin[l] >= end[l]) {
        begin[l] = end[l] = 0;
        continue;
      }
      active[l] = -1;
      first = std::min(first, begin[l]);
      last = std::max(last, end[l]);
    }
    if (first >= last) return hit;
    if (last - first <= 4 * guard)
      return lk::disturbed(c_->v.data(), c_->im.data(), lk::load(kinetic_limit_.data()), as_lanes(begin.data()),
                           as_lanes(end.data()), active, first, last);
    for (std::size_t l = 0; l < c_->lanes; ++l)
      if (active[l] && disturbed(l, begin[l], end[l])) hit[l] = -1;
    return hit;
  };
  bool grew = false;
  const lk::M left = check(true);
  for (std::size_t l = 0; l < c_->lanes; ++l)
    if (left[l]) lo_[l] = detail::grown_lo(lo_[l], guard), grew = true;
  const lk::M right = check(false);
  for (std::size_t l = 0; l < c_->lanes; ++l)
    if (right[l]) hi_[l] = detail::grown_hi(hi_[l], c_->n, guard), grew = true;
  if (!grew) return;
  union_lo_ = *std::min_element(lo_.begin(), lo_.begin() + static_cast<long>(c_->lanes));
  union_hi_ = *std::max_element(hi_.begin(), hi_.begin() + static_cast<long>(c_->lanes));
}

void LanePropagator::copy_lane(std::size_t lane, std::vector<double>& u, std::vector<double>& v) const {
  u.assign(c_->n, 0.0);
  v.assign(c_->n, 0.0);
  refresh_lane(lane, u, v);
}

void LanePropagator::refresh_lane(std::size_t lane, std::vector<double>& u, std::vector<double>& v) const {
  detail::check_lane(*c_, lane);
  if (u.size() != c_->n || v.size() != c_->n) throw InvalidInput("lane", ": vectors of another length to refresh");
  detail::take_lane(c_->u, lane, 1, W, u, lo_[lane], hi_[lane]);
  detail::take_lane(c_->v, lane, 0, W, v, lo_[lane], hi_[lane]);
}

}  // namespace granular
