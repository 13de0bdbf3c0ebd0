// The tangent map on W chains side by side (lane_tangent_propagator.hpp): tangent_map.cpp's step
// sequence and renormalization, with the kernels of detail/lane_tangent_kernels.hpp.
#include "granular/lanes/lane_tangent_propagator.hpp"

#include <cmath>
#include <string>

#include "granular/dynamics/detail/splitting_sequence.hpp"
#include "granular/error.hpp"
#include "granular/lanes/detail/lane_chains.hpp"
#include "granular/lanes/detail/lane_tangent_kernels.hpp"

namespace granular {

namespace lk = detail::lane_kernels;
using lk::W;

std::size_t LaneTangentPropagator::width() { return W; }

LaneTangentPropagator::~LaneTangentPropagator() = default;
LaneTangentPropagator::LaneTangentPropagator(LaneTangentPropagator&&) noexcept = default;
LaneTangentPropagator& LaneTangentPropagator::operator=(LaneTangentPropagator&&) noexcept = default;

LaneTangentPropagator::LaneTangentPropagator(std::span<const ForceLaw> laws, std::span<const Chain> chains,
                                             const SplittingScheme& scheme, double time_step,
                                             std::span<const State> initials, std::span<const State> deviations,
                                             const LyapunovConfig& config)
    : scheme_(scheme), tau_(time_step), config_(config),
      c_(std::make_unique<detail::LaneChains>(detail::interleave(laws, chains, scheme, time_step, initials, W))),
      n_(c_->n), lanes_(c_->lanes) {
  if (deviations.size() != c_->lanes)
    throw InvalidInput("deviation", ": " + std::to_string(deviations.size()) + " vectors for " +
                                        std::to_string(c_->lanes) + " chains (one each)");
  if (!(config.time_unit > 0) || !std::isfinite(config.time_unit))
    throw InvalidInput("time_unit", ": must be finite and > 0");
  du_.assign(c_->u.size(), 0.0);
  dv_.assign(c_->v.size(), 0.0);
  logs_.assign(W, 0.0);
  initial_log_norm_.assign(W, 0.0);
  failures_.assign(W, "");
  for (std::size_t l = 0; l < c_->lanes; ++l) {
    if (deviations[l].u.size() != c_->n || deviations[l].v.size() != c_->n)
      throw InvalidInput("deviation", ": must have one entry per bead");
    detail::put_lane(du_, l, deviations[l].u, 1, W);
    detail::put_lane(dv_, l, deviations[l].v, 0, W);
  }
  norms_.assign(W, 0.0);
  for (std::size_t l = 0; l < c_->lanes; ++l) {
    initial_log_norm_[l] = std::log(norm(l));
    if (!std::isfinite(initial_log_norm_[l]))
      throw InvalidInput("deviation", ": the initial deviation vector must be finite and non-zero");
  }
}

void LaneTangentPropagator::advance(std::size_t steps) {
  if (steps == 0) return;
  const lk::LaneLaw law{c_->p1.data(), c_->p2.data(), c_->p3.data(), c_->k.data(), c_->q.data()};
  double* u = c_->u.data();
  double* v = c_->v.data();
  const double* im = c_->im.data();
  const std::size_t n = c_->n;
  detail::with_kernel(*c_, [&](auto hz, auto gr, auto qu) {
    constexpr bool hertz = decltype(hz)::value, grounded = decltype(gr)::value, quartic = decltype(qu)::value;
    detail::splitting_sequence(
        scheme_, tau_, steps,
        [&](double h, double d) {
          lk::tangent_kick_and_drift<hertz, grounded, quartic>(law, u, du_.data(), v, dv_.data(), im, n, h, d);
          bond_updates_ += n + 1;
        },
        [&](double g, double d) {
          lk::tangent_correct_and_drift<hertz, grounded, quartic>(law, u, du_.data(), v, dv_.data(), im, n, g, d);
          bond_updates_ += n + 1;
        },
        [&](double d) { lk::tangent_drift(u, du_.data(), v, dv_.data(), n, d); },
        [&] {
          ++steps_;
          if (config_.renormalize_every > 0 && steps_ % config_.renormalize_every == 0) renormalize();
        });
  });
}

double LaneTangentPropagator::norm(std::size_t lane) const {
  if (norms_step_ != steps_) {  // every lane's at once, once per step they are asked at
    const lk::V squares = lk::squared_norms(du_.data(), dv_.data(), c_->n, config_.time_unit);
    for (std::size_t l = 0; l < W; ++l) norms_[l] = std::sqrt(squares[l]);
    norms_step_ = steps_;
  }
  return norms_[lane];
}

void LaneTangentPropagator::renormalize() {
  // TangentPropagator::renormalize per lane: w back to its initial norm, ln of the stretch summed.
  const lk::V squares = lk::squared_norms(du_.data(), dv_.data(), c_->n, config_.time_unit);
  lk::V scale{};
  for (std::size_t l = 0; l < W; ++l) {
    scale[l] = 1;
    if (l >= c_->lanes || !failures_[l].empty()) continue;
    const double w = std::sqrt(squares[l]);
    if (!(w > 0) || !std::isfinite(w)) {
      failures_[l] = "tangent map: the deviation vector became " + std::string(std::isfinite(w) ? "zero" : "non-finite");
      continue;
    }
    logs_[l] += std::log(w) - initial_log_norm_[l];
    scale[l] = std::exp(initial_log_norm_[l]) / w;
  }
  for (std::size_t i = 0; i < du_.size(); i += W) lk::store(du_.data() + i, lk::load(du_.data() + i) * scale);
  for (std::size_t i = 0; i < dv_.size(); i += W) lk::store(dv_.data() + i, lk::load(dv_.data() + i) * scale);
}

double LaneTangentPropagator::log_stretch(std::size_t lane) const {
  return logs_[lane] + std::log(norm(lane)) - initial_log_norm_[lane];
}

void LaneTangentPropagator::copy_lane(std::size_t lane, std::vector<double>& u, std::vector<double>& v) const {
  detail::check_lane(*c_, lane);
  u.resize(c_->n);
  v.resize(c_->n);
  detail::take_lane(c_->u, lane, 1, W, u, 0, c_->n);
  detail::take_lane(c_->v, lane, 0, W, v, 0, c_->n);
}

void LaneTangentPropagator::copy_deviation(std::size_t lane, std::vector<double>& du, std::vector<double>& dv) const {
  detail::check_lane(*c_, lane);
  du.resize(c_->n);
  dv.resize(c_->n);
  detail::take_lane(du_, lane, 1, W, du, 0, c_->n);
  detail::take_lane(dv_, lane, 0, W, dv, 0, c_->n);
}

}  // namespace granular
