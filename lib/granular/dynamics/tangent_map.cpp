#include "granular/dynamics/tangent_map.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <variant>

#include "granular/dynamics/detail/blocked_kernels.hpp"
#include "granular/dynamics/detail/splitting_sequence.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

// f_k''(x), the bond curvature the corrector's derivative needs (force_law.hpp's formulas).
inline double curvature(const HertzLaw::View& l, std::size_t k, double x, double stiff) {
  return hertz_curvature_of(l.overlap[k], x, stiff);
}
inline double curvature(const PolynomialLaw::View& l, std::size_t k, double x, double) {
  return polynomial_curvature_of(l.c2[k], l.c3[k], x);
}

// The conservative stepper's blocked kernels (detail/blocked_kernels.hpp) carrying the deviation
// vector along: the orbit's arithmetic is theirs expression for expression (the build has no FMA
// contraction), so the orbit is bit for bit the conservative stepper's on the whole chain, and
// drifts and correctors merge across steps as there. Padded arrays: u/du[i+1] is bead i, ends 0.
using detail::block;

// Kick v += h F/m, δv += h δF/m (δF_k = K_k δx_k), then the drift u += d v, δu += d δv. On-site
// springs (`grounded`, ks the k_n per bead, qs the q_n when `quartic`) add −k u − q u³ to F and
// −(k + 3 q u²) δu to δF, as the stepper's kernels. With `store`, each bond's K_k (at the positions
// before the drift) goes to `stiff_out` and, when quartic, each bead's k + 3 q u² to `onsite_out`,
// for the further deviation vectors (deviation_kick_and_drift).
template <bool grounded, bool quartic, bool store, class View>
void kick_and_drift(const View law, const double* __restrict ks, const double* __restrict qs, double* __restrict u,
                    double* __restrict du, double* __restrict f, double* __restrict kx, double* __restrict v,
                    double* __restrict dv, const double* __restrict im, std::size_t n, double h, double d,
                    double* __restrict stiff_out, double* __restrict onsite_out) {
  double stiff = 0;
  law.force_stiffness(0, u[0] - u[1], f[0], stiff);
  kx[0] = stiff * (du[0] - du[1]);
  if constexpr (store) stiff_out[0] = stiff;
  for (std::size_t b0 = 1; b0 <= n; b0 += block) {
    const std::size_t b1 = std::min(n + 1, b0 + block);
    // As in correct_and_drift: inlined, GCC cannot prove the arrays distinct and left the storing
    // variant of this loop scalar (scalar √): two deviation vectors cost 4.1× a conservative step.
#pragma GCC ivdep
    for (std::size_t k = b0; k < b1; ++k) {
      double s;
      law.force_stiffness(k, u[k] - u[k + 1], f[k], s);
      kx[k] = s * (du[k] - du[k + 1]);
      if constexpr (store) stiff_out[k] = s;
    }
    for (std::size_t k = b0; k < b1; ++k) {
      double force = f[k - 1] - f[k], dforce = kx[k - 1] - kx[k];
      if constexpr (grounded) {
        force -= onsite_restoring<quartic>(ks, qs, k - 1, u[k]);
        const double s = onsite_hessian<quartic>(ks, qs, k - 1, u[k]);
        dforce -= s * du[k];
        if constexpr (quartic && store) onsite_out[k - 1] = s;
      }
      v[k - 1] += h * im[k - 1] * force;
      u[k] += d * v[k - 1];
      dv[k - 1] += h * im[k - 1] * dforce;
      du[k] += d * dv[k - 1];
    }
  }
}

// Bond k of a corrector: force, stiffness, δF_k = K_k δx_k and δK_k = f_k'' δx_k (with `store`,
// f_k'' itself to curv[k], for the further deviation vectors).
template <bool store, class View>
inline void corrector_bond(const View law, const double* __restrict u, const double* __restrict du, double* f,
                           double* stiff, double* kx, double* cx, double* curv, std::size_t k) {
  const double x = u[k] - u[k + 1], dx = du[k] - du[k + 1];
  law.force_stiffness(k, x, f[k], stiff[k]);
  kx[k] = stiff[k] * dx;
  const double c = curvature(law, k, x, stiff[k]);
  cx[k] = c * dx;
  if constexpr (store) curv[k] = c;
}

// Bead i of a corrector, once a and da of beads i − 1 … i + 1 (padded i … i + 2) are known. On-site
// springs: ks holds each bead's Hessian entry (k_n, or k_n + 3 q_n u_n² from the bead pass when
// `quartic`, whose curvature 6 q_n u_n is in oc).
template <bool grounded, bool quartic>
inline void corrector_bead(const double* __restrict ks, const double* __restrict oc, double* __restrict u,
                           double* __restrict du, const double* __restrict stiff, const double* __restrict cx,
                           const double* __restrict a, const double* __restrict da, double* __restrict v,
                           double* __restrict dv, const double* __restrict im, std::size_t i, double c, double d) {
  double g = stiff[i] * (a[i] - a[i + 1]) - stiff[i + 1] * (a[i + 1] - a[i + 2]);
  double dg = cx[i] * (a[i] - a[i + 1]) + stiff[i] * (da[i] - da[i + 1]) - cx[i + 1] * (a[i + 1] - a[i + 2]) -
              stiff[i + 1] * (da[i + 1] - da[i + 2]);
  if constexpr (grounded) {
    g -= ks[i] * a[i + 1];
    dg -= ks[i] * da[i + 1];
    if constexpr (quartic) dg -= oc[i] * du[i + 1] * a[i + 1];
  }
  v[i] += c * im[i] * g;
  dv[i] += c * im[i] * dg;
  u[i + 1] += d * v[i];
  du[i + 1] += d * dv[i];
}

// The corrector v_i += c im_i G_i, G_i = K_i (a_{i−1} − a_i) − K_{i+1} (a_i − a_{i+1}), and its
// derivative δG_i (δa_i = im_i (δF_i − δF_{i+1})), then the drift, blocked as
// detail::correct_and_drift; a and da are padded like u, 0 at the walls. On-site springs add
// −h_i a_i to G_i and −h_i δa_i to δG_i, with h_i = k_i (linear springs: no curvature term) or,
// when `quartic`, h_i = k_i + 3 q_i u_i², which adds −6 q_i u_i δu_i a_i to δG_i; the bead pass
// leaves h_i in oh and 6 q_i u_i in oc.
// With `store`, stiff, f_k'' (curv), a (and oh, oc) are left for the further deviation vectors
// (deviation_correct_and_drift), all at the positions before the drift.
template <bool grounded, bool quartic, bool store, class View>
void correct_and_drift(const View law, const double* __restrict ks, const double* __restrict qs, double* __restrict u,
                       double* __restrict du, double* __restrict f, double* __restrict stiff, double* __restrict kx,
                       double* __restrict cx, double* __restrict a, double* __restrict da, double* __restrict v,
                       double* __restrict dv, const double* __restrict im, std::size_t n, double c, double d,
                       double* __restrict curv, double* __restrict oh, double* __restrict oc) {
  // The Hessian entries the beads read: the springs' own k_n, or the bead pass's.
  const double* hs = quartic ? oh : ks;
  corrector_bond<store>(law, u, du, f, stiff, kx, cx, curv, 0);
  corrector_bond<store>(law, u, du, f, stiff, kx, cx, curv, 1);
  double first = f[0] - f[1], dfirst = kx[0] - kx[1];
  if constexpr (grounded) {
    first -= onsite_restoring<quartic>(ks, qs, 0, u[1]);
    const double h = onsite_hessian<quartic>(ks, qs, 0, u[1]);
    dfirst -= h * du[1];
    if constexpr (quartic) {
      oh[0] = h;
      oc[0] = onsite_curvature(qs, 0, u[1]);
    }
  }
  a[1] = im[0] * first;
  da[1] = im[0] * dfirst;
  for (std::size_t b0 = 2; b0 <= n; b0 += block) {
    const std::size_t b1 = std::min(n + 1, b0 + block);
    // The arrays are distinct (the propagator's own); once this is inlined GCC cannot prove it and
    // left this loop and the bead loop below scalar: a tangent step cost 3.2× a conservative one.
#pragma GCC ivdep
    for (std::size_t k = b0; k < b1; ++k) {
      const double x = u[k] - u[k + 1], dx = du[k] - du[k + 1];
      double force, s;
      law.force_stiffness(k, x, force, s);
      f[k] = force;
      stiff[k] = s;
      kx[k] = s * dx;
      const double cv = curvature(law, k, x, s);
      cx[k] = cv * dx;
      if constexpr (store) curv[k] = cv;
    }
    for (std::size_t k = b0; k < b1; ++k) {
      double force = f[k - 1] - f[k], dforce = kx[k - 1] - kx[k];
      if constexpr (grounded) {
        force -= onsite_restoring<quartic>(ks, qs, k - 1, u[k]);
        const double h = onsite_hessian<quartic>(ks, qs, k - 1, u[k]);
        dforce -= h * du[k];
        if constexpr (quartic) {
          oh[k - 1] = h;
          oc[k - 1] = onsite_curvature(qs, k - 1, u[k]);
        }
      }
      a[k] = im[k - 1] * force;
      da[k] = im[k - 1] * dforce;
    }
#pragma GCC ivdep
    for (std::size_t k = b0; k < b1; ++k)
      corrector_bead<grounded, quartic>(hs, oc, u, du, stiff, cx, a, da, v, dv, im, k - 2, c, d);
  }
  corrector_bead<grounded, quartic>(hs, oc, u, du, stiff, cx, a, da, v, dv, im, n - 1, c, d);  // a, da[n+1] are 0
}

void drift(double* __restrict u, double* __restrict du, const double* __restrict v, const double* __restrict dv,
           std::size_t n, double d) {
  for (std::size_t i = 0; i < n; ++i) {
    u[i + 1] += d * v[i];
    du[i + 1] += d * dv[i];
  }
}

// A further deviation vector through the kick and drift whose K_k the orbit's pass stored: the
// same expressions as kick_and_drift's δ part, every K_k δx_k taken before the drift moves δu. ks
// holds the beads' on-site Hessian entries (k_n, or those the orbit's pass stored when quartic).
template <bool grounded>
void deviation_kick_and_drift(const double* __restrict stiff, const double* __restrict ks, double* __restrict du,
                              double* __restrict kx, double* __restrict dv, const double* __restrict im, std::size_t n,
                              double h, double d) {
  for (std::size_t k = 0; k <= n; ++k) kx[k] = stiff[k] * (du[k] - du[k + 1]);
  for (std::size_t k = 1; k <= n; ++k) {
    double dforce = kx[k - 1] - kx[k];
    if constexpr (grounded) dforce -= ks[k - 1] * du[k];
    dv[k - 1] += h * im[k - 1] * dforce;
    du[k] += d * dv[k - 1];
  }
}

// A further deviation vector through the corrector and drift, from the orbit pass's K_k, f_k''
// and accelerations a: correct_and_drift's δ part (da padded like du, 0 at the walls). ks as in
// deviation_kick_and_drift; when quartic, oc holds the orbit pass's on-site curvatures 6 q_n u_n.
template <bool grounded, bool quartic>
void deviation_correct_and_drift(const double* __restrict stiff, const double* __restrict curv,
                                 const double* __restrict a, const double* __restrict ks, const double* __restrict oc,
                                 double* __restrict du, double* __restrict kx, double* __restrict cx,
                                 double* __restrict da, double* __restrict dv, const double* __restrict im,
                                 std::size_t n, double c, double d) {
  for (std::size_t k = 0; k <= n; ++k) {
    const double dx = du[k] - du[k + 1];
    kx[k] = stiff[k] * dx;
    cx[k] = curv[k] * dx;
  }
  for (std::size_t k = 1; k <= n; ++k) {
    double dforce = kx[k - 1] - kx[k];
    if constexpr (grounded) dforce -= ks[k - 1] * du[k];
    da[k] = im[k - 1] * dforce;
  }
  for (std::size_t i = 0; i < n; ++i) {
    double dg = cx[i] * (a[i] - a[i + 1]) + stiff[i] * (da[i] - da[i + 1]) - cx[i + 1] * (a[i + 1] - a[i + 2]) -
                stiff[i + 1] * (da[i + 1] - da[i + 2]);
    if constexpr (grounded) dg -= ks[i] * da[i + 1];
    if constexpr (quartic) dg -= oc[i] * du[i + 1] * a[i + 1];
    dv[i] += c * im[i] * dg;
    du[i + 1] += d * dv[i];
  }
}

template <BondForceLaw Law>
class SplittingTangentPropagator final : public TangentPropagator {
 public:
  SplittingTangentPropagator(const Law& law, const Chain& chain, const SplittingScheme& scheme, double tau,
                             const State& initial, const std::vector<State>& deviations, const LyapunovConfig& config,
                             std::function<void(TangentPropagator&)> orthonormalize)
      : law_(law), scheme_(scheme), tau_(tau), n_(chain.size()), extra_(deviations.size() - 1), config_(config),
        orthonormalize_(std::move(orthonormalize)) {
    const State& deviation = deviations.front();
    up_.assign(n_ + 2, 0.0);
    dup_.assign(n_ + 2, 0.0);
    std::copy(initial.u.begin(), initial.u.end(), up_.begin() + 1);
    std::copy(deviation.u.begin(), deviation.u.end(), dup_.begin() + 1);
    v_ = initial.v;
    dv_ = deviation.v;
    im_ = chain.inverse_mass;
    for (auto* a : {&f_, &stiff_, &kx_, &cx_}) a->assign(n_ + 1, 0.0);
    ap_.assign(n_ + 2, 0.0);
    dap_.assign(n_ + 2, 0.0);
    if (law_.quartic()) {
      onsite_hessian_.assign(n_, 0.0);
      onsite_curvature_.assign(n_, 0.0);
    }
    if (extra_ > 0) {
      for (auto* a : {&curv_, &xkx_, &xcx_}) a->assign(n_ + 1, 0.0);
      xda_.assign(n_ + 2, 0.0);
      xdu_.assign(extra_ * (n_ + 2), 0.0);
      xdv_.assign(extra_ * n_, 0.0);
      for (std::size_t j = 1; j <= extra_; ++j) set_deviation(j, deviations[j].u, deviations[j].v);
    }
    initial_log_norm_ = std::log(norm());
    if (!std::isfinite(initial_log_norm_))
      throw InvalidInput("deviation", ": the initial deviation vector must be finite and non-zero");
  }

  void advance(std::size_t steps) override {
    if (steps == 0) return;
    if (law_.quartic()) extra_ > 0 ? run<true, true, true>(steps) : run<true, true, false>(steps);
    else if (law_.grounded()) extra_ > 0 ? run<true, false, true>(steps) : run<true, false, false>(steps);
    else extra_ > 0 ? run<false, false, true>(steps) : run<false, false, false>(steps);
  }

  // advance() with the on-site springs (linear or with a quartic part) compiled in or out, and with
  // (`several`) or without further deviation vectors: the orbit and vector 0 go through the fused
  // kernels, which then leave K_k, f_k'', a (and the on-site Hessian entries) for the others. The
  // orbit's arithmetic is the same either way.
  template <bool grounded, bool quartic, bool several>
  void run(std::size_t steps) {
    const auto view = law_.view();
    const double* ks = view.onsite;
    const double* qs = view.onsite_quartic;
    // The Hessian entries further vectors read: k_n, or k_n + 3 q_n u_n² as the orbit's pass left them.
    const double* hs = quartic ? onsite_hessian_.data() : ks;
    // The conservative stepper's sequence (detail/splitting_sequence.hpp). A renormalization inside
    // a merged boundary scales w a fraction of a step early; the map is linear, so the sum of the
    // logarithms telescopes to the same X1.
    detail::splitting_sequence(
        scheme_, tau_, steps,
        [&](double h, double after) {
          kick_and_drift<grounded, quartic, several>(view, ks, qs, up_.data(), dup_.data(), f_.data(), kx_.data(),
                                                     v_.data(), dv_.data(), im_.data(), n_, h, after, stiff_.data(),
                                                     onsite_hessian_.data());
          if constexpr (several)
            for (std::size_t e = 0; e < extra_; ++e)
              deviation_kick_and_drift<grounded>(stiff_.data(), hs, xdu(e), xkx_.data(), xdv(e), im_.data(), n_, h,
                                                 after);
          bond_updates_ += n_ + 1;
        },
        [&](double c, double after) { correct<grounded, quartic, several>(view, c, after); },
        [&](double d) {
          drift(up_.data(), dup_.data(), v_.data(), dv_.data(), n_, d);
          for (std::size_t e = 0; e < extra_; ++e)
            for (std::size_t i = 0; i < n_; ++i) xdu(e)[i + 1] += d * xdv(e)[i];
        },
        [&] {
          ++steps_;
          if (config_.renormalize_every > 0 && steps_ % config_.renormalize_every == 0) {
            if (extra_ > 0) orthonormalize_(*this);  // the owner's, between steps as renormalize()
            else renormalize();
          }
        });
  }

  std::span<const double> displacement() const override { return {up_.data() + 1, n_}; }
  std::span<const double> velocity() const override { return {v_.data(), n_}; }
  std::span<const double> deviation_displacement() const override { return {dup_.data() + 1, n_}; }
  std::span<const double> deviation_velocity() const override { return {dv_.data(), n_}; }
  std::size_t deviation_count() const override { return extra_ + 1; }
  std::span<const double> deviation_displacement(std::size_t j) const override {
    return j == 0 ? deviation_displacement() : std::span<const double>{xdu_.data() + (j - 1) * (n_ + 2) + 1, n_};
  }
  std::span<const double> deviation_velocity(std::size_t j) const override {
    return j == 0 ? deviation_velocity() : std::span<const double>{xdv_.data() + (j - 1) * n_, n_};
  }
  void set_deviation(std::size_t j, std::span<const double> du, std::span<const double> dv) override {
    if (j > extra_ || du.size() != n_ || dv.size() != n_)
      throw InvalidInput("deviation", ": no vector " + std::to_string(j) + " of " + std::to_string(n_) + " beads");
    double* u = j == 0 ? dup_.data() : xdu(j - 1);
    double* v = j == 0 ? dv_.data() : xdv(j - 1);
    std::copy(du.begin(), du.end(), u + 1);
    std::copy(dv.begin(), dv.end(), v);
  }
  double time_step() const override { return tau_; }
  std::uint64_t steps_done() const override { return steps_; }
  std::uint64_t bond_updates() const override { return bond_updates_; }
  double log_stretch() const override { return logs_ + std::log(norm()) - initial_log_norm_; }
  double time_unit() const override { return config_.time_unit; }

 private:
  template <bool grounded, bool quartic, bool several, class View>
  void correct(const View view, double c, double d) {
    double* oh = onsite_hessian_.data();
    double* oc = onsite_curvature_.data();
    correct_and_drift<grounded, quartic, several>(view, view.onsite, view.onsite_quartic, up_.data(), dup_.data(),
                                                  f_.data(), stiff_.data(), kx_.data(), cx_.data(), ap_.data(),
                                                  dap_.data(), v_.data(), dv_.data(), im_.data(), n_, c, d,
                                                  curv_.data(), oh, oc);
    if constexpr (several)
      for (std::size_t e = 0; e < extra_; ++e)
        deviation_correct_and_drift<grounded, quartic>(stiff_.data(), curv_.data(), ap_.data(),
                                                       quartic ? oh : view.onsite, oc, xdu(e), xkx_.data(), xcx_.data(),
                                                       xda_.data(), xdv(e), im_.data(), n_, c, d);
    bond_updates_ += n_ + 1;
  }

  // Further vector e (vector e + 1): δu padded like u, δv.
  double* xdu(std::size_t e) { return xdu_.data() + e * (n_ + 2); }
  double* xdv(std::size_t e) { return xdv_.data() + e * n_; }

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
  std::size_t n_, extra_;  ///< beads; deviation vectors beyond the first
  LyapunovConfig config_;
  std::vector<double> up_, dup_, v_, dv_, im_, f_, stiff_, kx_, cx_, ap_, dap_;
  // The further vectors' (several); a kick leaves its K_k in stiff_, which only the corrector
  // otherwise uses (and fills anew).
  std::vector<double> curv_, xkx_, xcx_, xda_, xdu_, xdv_;
  // Quartic on-site springs: each bead's Hessian entry k + 3 q u² and curvature 6 q u, at the
  // positions before a drift (empty otherwise).
  std::vector<double> onsite_hessian_, onsite_curvature_;
  std::function<void(TangentPropagator&)> orthonormalize_;  // several vectors' renormalization
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

State TangentPropagator::deviation(std::size_t j) const {
  const auto du = deviation_displacement(j), dv = deviation_velocity(j);
  State s(du.size());
  std::copy(du.begin(), du.end(), s.u.begin());
  std::copy(dv.begin(), dv.end(), s.v.begin());
  return s;
}

std::vector<State> TangentPropagator::deviations() const {
  std::vector<State> out;
  for (std::size_t j = 0; j < deviation_count(); ++j) out.push_back(deviation(j));
  return out;
}

TangentImages propagate_deviations(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                                   double time_step, std::size_t steps, const State& initial,
                                   const std::vector<State>& deviations) {
  TangentImages out;
  out.deviations.reserve(deviations.size());
  for (const State& w : deviations) {
    auto p =
        make_tangent_propagator(law, chain, scheme, time_step, initial, w, {.enabled = true, .renormalize_every = 0});
    p->advance(steps);
    out.deviations.push_back(p->deviation(0));
    if (out.deviations.size() == 1) out.orbit = p->state();
  }
  if (deviations.empty()) {
    auto p = make_splitting_propagator(law, chain, scheme, time_step, initial, {.enabled = false});
    p->advance(steps);
    out.orbit = p->state();
  }
  return out;
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
  return make_tangent_propagator(law, chain, scheme, time_step, initial, std::vector<State>{deviation}, config);
}

std::unique_ptr<TangentPropagator> make_tangent_propagator(const ForceLaw& law, const Chain& chain,
                                                           const SplittingScheme& scheme, double time_step,
                                                           const State& initial, const std::vector<State>& deviations,
                                                           const LyapunovConfig& config,
                                                           std::function<void(TangentPropagator&)> orthonormalize) {
  validate_propagation(chain, time_step, initial);
  if (deviations.empty() || deviations.size() > 2 * chain.size())
    throw InvalidInput("deviation", ": between 1 and 2N = " + std::to_string(2 * chain.size()) + " vectors");
  for (const State& deviation : deviations)
    if (deviation.u.size() != chain.size() || deviation.v.size() != chain.size())
      throw InvalidInput("deviation", ": must have one entry per bead");
  if (!(config.time_unit > 0) || !std::isfinite(config.time_unit))
    throw InvalidInput("time_unit", ": must be finite and > 0");
  if (deviations.size() > 1 && config.renormalize_every > 0 && !orthonormalize)
    throw InvalidInput("renormalize", ": several deviation vectors are re-orthonormalized together, by their owner");
  return std::visit(
      [&](const auto& l) -> std::unique_ptr<TangentPropagator> {
        using Law = std::decay_t<decltype(l)>;
        return std::make_unique<SplittingTangentPropagator<Law>>(l, chain, scheme, time_step, initial, deviations,
                                                                 config, orthonormalize);
      },
      law);
}

}  // namespace granular
