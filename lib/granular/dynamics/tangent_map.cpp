#include "granular/dynamics/tangent_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "granular/error.hpp"

namespace granular {
namespace {

// f_k''(x), the bond curvature the corrector's derivative needs, from the stiffness just computed.
// Hertz: (3/4) A [δ]_+^{−1/2} = K/(2δ), 0 for an open contact (K = 0 there; unbounded as a contact
// closes, where the orbit itself is only C¹); no second square root, and branch-free.
inline double curvature(const HertzLaw::View& l, std::size_t k, double x, double stiff) {
  return stiff / (2 * std::max(l.overlap[k] + x, std::numeric_limits<double>::min()));
}
inline double curvature(const PolynomialLaw::View& l, std::size_t k, double x, double) {
  return 2 * l.c2[k] + 6 * l.c3[k] * x;
}

// Padded arrays as in detail/plain_step.hpp: up/dup[i+1] is bead i, ends 0 (the walls).
void drift(double* __restrict up, double* __restrict dup, const double* __restrict v, const double* __restrict dv,
           std::size_t n, double d) {
  for (std::size_t i = 0; i < n; ++i) {
    up[i + 1] += d * v[i];
    dup[i + 1] += d * dv[i];
  }
}

template <class View>
void kick(const View law, const double* __restrict up, const double* __restrict dup, double* __restrict f,
          double* __restrict stiff, double* __restrict dx, double* __restrict v, double* __restrict dv,
          const double* __restrict im, std::size_t n, double h) {
  for (std::size_t k = 0; k <= n; ++k) {
    law.force_stiffness(k, up[k] - up[k + 1], f[k], stiff[k]);
    dx[k] = dup[k] - dup[k + 1];
  }
  for (std::size_t i = 0; i < n; ++i) {
    v[i] += h * im[i] * (f[i] - f[i + 1]);
    dv[i] += h * im[i] * (stiff[i] * dx[i] - stiff[i + 1] * dx[i + 1]);
  }
}

// The corrector v_i += c im_i G_i, G_i = K_i (a_{i−1} − a_i) − K_{i+1} (a_i − a_{i+1}), and its
// derivative δG_i (K_k' = f_k'' δx_k, δa_i = im_i (K_i δx_i − K_{i+1} δx_{i+1})).
template <class View>
void correct(const View law, const double* __restrict up, const double* __restrict dup, double* __restrict f,
             double* __restrict stiff, double* __restrict curv, double* __restrict dx, double* __restrict ap,
             double* __restrict dap, double* __restrict v, double* __restrict dv, const double* __restrict im,
             std::size_t n, double c) {
  for (std::size_t k = 0; k <= n; ++k) {
    const double x = up[k] - up[k + 1];
    law.force_stiffness(k, x, f[k], stiff[k]);
    curv[k] = curvature(law, k, x, stiff[k]);
    dx[k] = dup[k] - dup[k + 1];
  }
  for (std::size_t i = 0; i < n; ++i) {
    ap[i + 1] = im[i] * (f[i] - f[i + 1]);
    dap[i + 1] = im[i] * (stiff[i] * dx[i] - stiff[i + 1] * dx[i + 1]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double left = ap[i] - ap[i + 1], right = ap[i + 1] - ap[i + 2];
    v[i] += c * im[i] * (stiff[i] * left - stiff[i + 1] * right);
    dv[i] += c * im[i] *
             (curv[i] * dx[i] * left + stiff[i] * (dap[i] - dap[i + 1]) - curv[i + 1] * dx[i + 1] * right -
              stiff[i + 1] * (dap[i + 1] - dap[i + 2]));
  }
}

template <BondForceLaw Law>
class SplittingTangentPropagator final : public TangentPropagator {
 public:
  SplittingTangentPropagator(const Law& law, const Chain& chain, const SplittingScheme& scheme, double tau,
                             const State& initial, const State& deviation, const LyapunovConfig& config)
      : law_(law), scheme_(scheme), tau_(tau), n_(chain.size()), config_(config) {
    up_.assign(n_ + 2, 0.0);
    dup_.assign(n_ + 2, 0.0);
    std::copy(initial.u.begin(), initial.u.end(), up_.begin() + 1);
    std::copy(deviation.u.begin(), deviation.u.end(), dup_.begin() + 1);
    v_ = initial.v;
    dv_ = deviation.v;
    im_ = chain.inverse_mass;
    for (auto* a : {&f_, &stiff_, &curv_, &dx_}) a->assign(n_ + 1, 0.0);
    ap_.assign(n_ + 2, 0.0);
    dap_.assign(n_ + 2, 0.0);
    initial_log_norm_ = std::log(norm());
    if (!std::isfinite(initial_log_norm_))
      throw InvalidInput("deviation", ": the initial deviation vector must be finite and non-zero");
  }

  void advance(std::size_t steps) override {
    const auto view = law_.view();
    const double g = scheme_.corrector * tau_ * tau_ * tau_;
    const auto& a = scheme_.drift;
    const auto& b = scheme_.kick;
    for (std::size_t s = 0; s < steps; ++s) {
      if (g != 0) correct_both(view, g);
      for (std::size_t j = 0; j < b.size(); ++j) {
        drift(up_.data(), dup_.data(), v_.data(), dv_.data(), n_, a[j] * tau_);
        kick(view, up_.data(), dup_.data(), f_.data(), stiff_.data(), dx_.data(), v_.data(), dv_.data(), im_.data(), n_,
             b[j] * tau_);
      }
      drift(up_.data(), dup_.data(), v_.data(), dv_.data(), n_, a.back() * tau_);
      if (g != 0) correct_both(view, g);
      ++steps_;
      if (config_.renormalize_every > 0 && steps_ % config_.renormalize_every == 0) renormalize();
    }
    bond_updates_ += steps * (scheme_.kick.size() + (g != 0 ? 2 : 0)) * (n_ + 1);
  }

  std::span<const double> displacement() const override { return {up_.data() + 1, n_}; }
  std::span<const double> velocity() const override { return {v_.data(), n_}; }
  std::span<const double> deviation_displacement() const override { return {dup_.data() + 1, n_}; }
  std::span<const double> deviation_velocity() const override { return {dv_.data(), n_}; }
  double time_step() const override { return tau_; }
  std::uint64_t steps_done() const override { return steps_; }
  std::uint64_t bond_updates() const override { return bond_updates_; }
  double log_stretch() const override { return logs_ + std::log(norm()) - initial_log_norm_; }
  double time_unit() const override { return config_.time_unit; }

 private:
  template <class View>
  void correct_both(const View view, double g) {
    correct(view, up_.data(), dup_.data(), f_.data(), stiff_.data(), curv_.data(), dx_.data(), ap_.data(), dap_.data(),
            v_.data(), dv_.data(), im_.data(), n_, g);
  }

  double norm() const {
    const double t = config_.time_unit;
    double part[4] = {0, 0, 0, 0};  // independent partial sums, fixed order
    for (std::size_t i = 0; i < n_; ++i) part[i % 4] += dup_[i + 1] * dup_[i + 1] + t * t * dv_[i] * dv_[i];
    return std::sqrt((part[0] + part[1]) + (part[2] + part[3]));
  }

  void renormalize() {
    const double w = norm();
    if (!(w > 0) || !std::isfinite(w))
      throw NumericalError("tangent map: the deviation vector became " +
                           std::string(std::isfinite(w) ? "zero" : "non-finite"));
    logs_ += std::log(w) - initial_log_norm_;
    const double scale = std::exp(initial_log_norm_) / w;  // back to the initial norm
    for (double& x : dup_) x *= scale;
    for (double& x : dv_) x *= scale;
  }

  Law law_;
  SplittingScheme scheme_;
  double tau_;
  std::size_t n_;
  LyapunovConfig config_;
  std::vector<double> up_, dup_, v_, dv_, im_, f_, stiff_, curv_, dx_, ap_, dap_;
  std::uint64_t steps_ = 0, bond_updates_ = 0;
  double logs_ = 0, initial_log_norm_ = 0;
};

}  // namespace

std::vector<double> TangentPropagator::deviation_distribution() const {
  const auto du = deviation_displacement();
  const auto dv = deviation_velocity();
  const double t = time_unit();
  std::vector<double> w(du.size());
  double total = 0;
  for (std::size_t i = 0; i < w.size(); ++i) total += w[i] = du[i] * du[i] + t * t * dv[i] * dv[i];
  for (double& x : w) x /= total;
  return w;
}

State localized_deviation(std::size_t beads, std::size_t site, double time_unit) {
  if (site >= beads) throw InvalidInput("site", " " + std::to_string(site + 1) + ": outside the chain");
  State w(beads);
  w.u[site] = 1;
  w.v[site] = 1 / time_unit;
  return w;
}

std::unique_ptr<TangentPropagator> make_tangent_propagator(const ForceLaw& law, const Chain& chain,
                                                           const SplittingScheme& scheme, double time_step,
                                                           const State& initial, const State& deviation,
                                                           const LyapunovConfig& config) {
  validate_propagation(chain, time_step, initial);
  if (deviation.u.size() != chain.size() || deviation.v.size() != chain.size())
    throw InvalidInput("deviation", ": must have one entry per bead");
  if (!(config.time_unit > 0) || !std::isfinite(config.time_unit))
    throw InvalidInput("time_unit", ": must be finite and > 0");
  return std::visit(
      [&](const auto& l) -> std::unique_ptr<TangentPropagator> {
        using Law = std::decay_t<decltype(l)>;
        return std::make_unique<SplittingTangentPropagator<Law>>(l, chain, scheme, time_step, initial, deviation,
                                                                 config);
      },
      law);
}

}  // namespace granular
