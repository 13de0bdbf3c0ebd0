// The splitting scheme on W chains side by side (lane_propagator.hpp): the step sequence of
// splitting_propagator.cpp, with the lane kernels of detail/lane_kernels.hpp.
#include "granular/dynamics/lane_propagator.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <tuple>
#include <variant>

#include "granular/dynamics/detail/lane_kernels.hpp"
#include "granular/dynamics/detail/splitting_sequence.hpp"
#include "granular/dynamics/detail/window_rule.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/error.hpp"

namespace granular {

namespace {

namespace lk = detail::lane_kernels;
using lk::W;

/// Calls `run(hertz, grounded, quartic)` with the three as compile-time constants.
template <class Run>
void with_kernel(bool hertz, bool grounded, bool quartic, Run&& run) {
  const auto on = [&](auto h) {
    if (quartic) run(h, std::true_type{}, std::true_type{});
    else if (grounded) run(h, std::true_type{}, std::false_type{});
    else run(h, std::false_type{}, std::false_type{});
  };
  if (hertz) on(std::true_type{});
  else on(std::false_type{});
}

lk::M as_lanes(const std::size_t* x) {
  lk::M out{};
  for (std::size_t l = 0; l < W; ++l) out[l] = static_cast<long>(x[l]);
  return out;
}

}  // namespace

std::size_t LanePropagator::width() { return W; }

LanePropagator::LanePropagator(std::span<const ForceLaw> laws, std::span<const Chain> chains,
                               const SplittingScheme& scheme, double time_step, std::span<const State> initials,
                               const ActiveWindow& window)
    : scheme_(scheme), tau_(time_step), n_(chains.empty() ? 0 : chains.front().size()), lanes_(chains.size()),
      window_(window) {
  if (chains.empty() || chains.size() > W)
    throw InvalidInput("lanes", " " + std::to_string(chains.size()) + ": between 1 and " + std::to_string(W) +
                                    " chains side by side on this CPU");
  if (laws.size() != lanes_ || initials.size() != lanes_)
    throw InvalidInput("lanes: " + std::to_string(lanes_) + " chains, " + std::to_string(laws.size()) + " laws, " +
                       std::to_string(initials.size()) + " initial states");
  if (scheme.drift.size() != scheme.kick.size() + 1 || scheme.kick.empty())
    throw InvalidInput("scheme " + scheme.name + ": needs s kicks and s+1 drifts");
  if (window.enabled && !(window.threshold >= 0)) throw InvalidInput("active window threshold must be >= 0");
  hertz_ = std::holds_alternative<HertzLaw>(laws[0]);
  grounded_ = granular::grounded(laws[0]);
  quartic_ = std::visit([](const auto& l) { return l.quartic(); }, laws[0]);
  for (std::size_t l = 0; l < lanes_; ++l) {
    if (chains[l].size() != n_)
      throw InvalidInput("lanes: chain " + std::to_string(l) + " has " + std::to_string(chains[l].size()) +
                         " beads, chain 0 " + std::to_string(n_) + "; side by side they must have one length");
    const bool same_kind = std::holds_alternative<HertzLaw>(laws[l]) == hertz_ &&
                           granular::grounded(laws[l]) == grounded_ &&
                           std::visit([](const auto& x) { return x.quartic(); }, laws[l]) == quartic_;
    if (!same_kind) throw InvalidInput("lanes: the laws of chains 0 and " + std::to_string(l) + " are of other kinds");
    validate_propagation(chains[l], time_step, initials[l]);
  }

  u_.assign((n_ + 2) * W, 0.0);
  v_.assign(n_ * W, 0.0);
  im_.assign(n_ * W, 0.0);
  p1_.assign((n_ + 1) * W, 0.0);
  p2_.assign((n_ + 1) * W, 0.0);
  p3_.assign((n_ + 1) * W, 0.0);
  if (grounded_) k_.assign(n_ * W, 0.0);
  if (quartic_) q_.assign(n_ * W, 0.0);
  lo_.assign(W, 0);
  hi_.assign(W, 0);  // idle lanes: an empty window, never touched
  kinetic_limit_.assign(W, 0.0);
  bond_updates_.assign(W, 0);
  // Idle lanes carry lane 0's coefficients at rest: finite numbers, every force 0.
  for (std::size_t l = 0; l < W; ++l) {
    const std::size_t from = l < lanes_ ? l : 0;
    std::visit(
        [&](const auto& law) {
          const auto view = law.view();
          const double* p[3];
          if constexpr (std::is_same_v<std::decay_t<decltype(law)>, HertzLaw>)
            p[0] = view.contact, p[1] = view.overlap, p[2] = view.rest;
          else p[0] = view.c1, p[1] = view.c2, p[2] = view.c3;
          for (std::size_t k = 0; k <= n_; ++k) {
            p1_[k * W + l] = p[0][k];
            p2_[k * W + l] = p[1][k];
            p3_[k * W + l] = p[2][k];
          }
          for (std::size_t i = 0; i < n_; ++i) {
            if (grounded_) k_[i * W + l] = view.onsite[i];
            if (quartic_) q_[i * W + l] = view.onsite_quartic[i];
          }
        },
        laws[from]);
    for (std::size_t i = 0; i < n_; ++i) im_[i * W + l] = chains[from].inverse_mass[i];
    if (l >= lanes_) continue;
    const State& s = initials[l];
    for (std::size_t i = 0; i < n_; ++i) {
      u_[(i + 1) * W + l] = s.u[i];
      v_[i * W + l] = s.v[i];
    }
    std::tie(lo_[l], hi_[l]) = detail::opened_window(s, window_);
    if (window_.enabled && window_.guard > 0) {
      kinetic_limit_[l] = 2 * window_.threshold * total_energy(laws[l], chains[l], s);
    }
  }
  union_lo_ = *std::min_element(lo_.begin(), lo_.begin() + static_cast<long>(lanes_));
  union_hi_ = *std::max_element(hi_.begin(), hi_.begin() + static_cast<long>(lanes_));
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

void LanePropagator::drift(double d) { lk::drift_only(u_.data(), v_.data(), union_lo_, union_hi_, d); }

void LanePropagator::pass(bool corrector, double weight, double d) {
  const lk::LaneLaw law{p1_.data(), p2_.data(), p3_.data(), k_.data(), q_.data()};
  const lk::M lo = as_lanes(lo_.data()), hi = as_lanes(hi_.data());
  with_kernel(hertz_, grounded_, quartic_, [&](auto hz, auto gr, auto qu) {
    constexpr bool hertz = decltype(hz)::value, grounded = decltype(gr)::value, quartic = decltype(qu)::value;
    if (corrector)
      lk::correct_and_drift<hertz, grounded, quartic>(law, u_.data(), v_.data(), im_.data(), lo, hi, union_lo_,
                                                      union_hi_, weight, d);
    else
      lk::kick_and_drift<hertz, grounded, quartic>(law, u_.data(), v_.data(), im_.data(), lo, hi, union_lo_, union_hi_,
                                                   weight, d);
  });
  count_updates();
}

void LanePropagator::count_updates() {
  for (std::size_t l = 0; l < lanes_; ++l) bond_updates_[l] += hi_[l] - lo_[l] + 1;
}

bool LanePropagator::disturbed(std::size_t lane, std::size_t begin, std::size_t end) const {
  for (std::size_t i = begin; i < end; ++i) {
    if (detail::disturbs(v_[i * W + lane], kinetic_limit_[lane], im_[i * W + lane])) return true;
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
    std::size_t first = n_, last = 0;
    for (std::size_t l = 0; l < lanes_; ++l) {
      std::tie(begin[l], end[l]) =
          left ? detail::left_edge(lo_[l], hi_[l], guard) : detail::right_edge(lo_[l], hi_[l], n_, guard);
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
      return lk::disturbed(v_.data(), im_.data(), lk::load(kinetic_limit_.data()), as_lanes(begin.data()),
                           as_lanes(end.data()), active, first, last);
    for (std::size_t l = 0; l < lanes_; ++l)
      if (active[l] && disturbed(l, begin[l], end[l])) hit[l] = -1;
    return hit;
  };
  bool grew = false;
  const lk::M left = check(true);
  for (std::size_t l = 0; l < lanes_; ++l)
    if (left[l]) lo_[l] = detail::grown_lo(lo_[l], guard), grew = true;
  const lk::M right = check(false);
  for (std::size_t l = 0; l < lanes_; ++l)
    if (right[l]) hi_[l] = detail::grown_hi(hi_[l], n_, guard), grew = true;
  if (!grew) return;
  union_lo_ = *std::min_element(lo_.begin(), lo_.begin() + static_cast<long>(lanes_));
  union_hi_ = *std::max_element(hi_.begin(), hi_.begin() + static_cast<long>(lanes_));
}

void LanePropagator::copy_lane(std::size_t lane, std::vector<double>& u, std::vector<double>& v) const {
  u.assign(n_, 0.0);
  v.assign(n_, 0.0);
  refresh_lane(lane, u, v);
}

void LanePropagator::refresh_lane(std::size_t lane, std::vector<double>& u, std::vector<double>& v) const {
  if (lane >= lanes_) throw InvalidInput("lane", " " + std::to_string(lane) + ": only " + std::to_string(lanes_));
  if (u.size() != n_ || v.size() != n_) throw InvalidInput("lane", ": vectors of another length to refresh");
  for (std::size_t i = lo_[lane]; i < hi_[lane]; ++i) {
    u[i] = u_[(i + 1) * W + lane];
    v[i] = v_[i * W + lane];
  }
}

}  // namespace granular
