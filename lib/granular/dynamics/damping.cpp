#include "granular/dynamics/damping.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <variant>

#include "granular/dynamics/detail/blocked_kernels.hpp"
#include "granular/dynamics/detail/vector_expm1.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

// Σ m v² with eight independent partial sums (a fixed order, so deterministic): a single
// accumulator would make the sum latency-bound and cost more than the damping itself. `before`
// and `after` run on each element just before and just after it is summed (the step boundary's
// neighbouring updates, fused into the one pass over v).
template <class Before, class After>
double twice_kinetic(const double* __restrict m, double* __restrict v, std::size_t n, Before before, After after) {
  double part[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8)
    for (std::size_t j = 0; j < 8; ++j) {
      before(i + j);
      part[j] += m[i + j] * v[i + j] * v[i + j];
      after(i + j);
    }
  for (; i < n; ++i) {
    before(i);
    part[0] += m[i] * v[i] * v[i];
    after(i);
  }
  return ((part[0] + part[1]) + (part[2] + part[3])) + ((part[4] + part[5]) + (part[6] + part[7]));
}
constexpr auto nothing = [](std::size_t) {};
double twice_kinetic(const double* __restrict m, double* __restrict v, std::size_t n) {
  return twice_kinetic(m, v, n, nothing, nothing);
}

// 1 − q of the exact pair flow g ← q g, q = e^{−2y} (y = hλ/2), without cancellation for small y,
// for bonds [lo, hi): on entry loss[k] holds y. The flow is L-stable: q → 0 for stiff contacts,
// where Crank–Nicolson's (1 − y)/(1 + y) → −1 made the pair's relative velocity flip sign every
// step. detail::expm1_nonpositive rather than std::expm1, so that the loops vectorize (and take
// the short series when every contact's y ≤ 1/32, as usual). loss2 (if not null): 1 − q², two
// pair steps.
void pair_losses(double* __restrict loss, double* __restrict loss2, std::size_t lo, std::size_t hi) {
  for (std::size_t k = lo; k < hi; ++k) loss[k] = -2 * loss[k];
  detail::expm1_nonpositive(loss + lo, hi - lo);
  for (std::size_t k = lo; k < hi; ++k) loss[k] = -loss[k];
  if (loss2)
    for (std::size_t k = lo; k < hi; ++k) loss2[k] = loss[k] * (2 - loss[k]);
}

// One exact pair step on the bonds k ∈ [lo, hi) of one parity; vp is padded (vp[k] is
// bead k−1, vp[0] = vp[n+1] = 0 the walls, which take no share and stay 0); share is
// DampingFlow::pair_share(parity). The two members' updates have the same form, so that the
// compiler vectorizes the pair as one unit.
void pair_damping(double* __restrict vp, const double* __restrict share, const double* __restrict loss, std::size_t lo,
                  std::size_t hi, std::size_t parity) {
  for (std::size_t k = lo + ((lo ^ parity) & 1); k < hi; k += 2) {
    const double g = loss[k] * (vp[k] - vp[k + 1]);
    vp[k] -= share[k] * g;
    vp[k + 1] -= share[k + 1] * g;
  }
}

void scale(double* __restrict v, std::size_t n, double factor) {
  for (std::size_t i = 0; i < n; ++i) v[i] *= factor;
}

}  // namespace

void validate(const Damping& d) {
  if (!std::isfinite(d.time) || d.time < 0)
    throw InvalidInput("damping_time", " " + format_number(d.time) + ": must be finite and >= 0 (0: none)");
  if (!std::isfinite(d.kk_gamma) || d.kk_gamma < 0)
    throw InvalidInput("kk_gamma", " " + format_number(d.kk_gamma) + ": must be finite and >= 0 (0: none)");
}

DampingFlow::DampingFlow(const Chain& chain, const Damping& damping)
    : damping_(damping), mass_(chain.mass), contact_(chain.contact), overlap_(chain.overlap) {
  validate(damping);
  const std::size_t n = chain.size();
  sum_im_.assign(n + 1, 0.0);
  share_even_.assign(n + 2, 0.0);
  share_odd_.assign(n + 2, 0.0);
  for (std::size_t k = 0; k <= n; ++k) {
    const double l = k > 0 ? chain.inverse_mass[k - 1] : 0.0, r = k < n ? chain.inverse_mass[k] : 0.0;
    sum_im_[k] = l + r;
    auto& share = k % 2 == 0 ? share_even_ : share_odd_;
    share[k] = l / (l + r);         // bead k−1 (position k) moves by −(1/m_{k−1})/(Σ 1/m) · g
    share[k + 1] = -(r / (l + r));  // bead k (position k+1) by +(1/m_k)/(Σ 1/m) · g
  }
  rate_.assign(n + 1, 0.0);
  rate_per_stiffness_.assign(n + 1, 0.0);
  vp_.assign(n + 2, 0.0);
  loss_.assign(n + 1, 0.0);
}

void DampingFlow::prepare(double h) {
  if (h == h_) return;
  h_ = h;
  for (std::size_t k = 0; k < rate_.size(); ++k) {
    const double per_contact = 0.5 * h * damping_.kk_gamma * sum_im_[k];
    rate_[k] = per_contact * contact_[k];
    rate_per_stiffness_[k] = per_contact / 1.5;
  }
}

double DampingFlow::apply(std::span<const double> u, std::span<double> v, double h) {
  // E_{h/2} O_h E_{h/2}: the even bonds' steps are half as long.
  return sweep(u, v, h, {std::size_t{0}, std::size_t{1}, std::size_t{0}}, {0.5, 1.0, 0.5});
}

double DampingFlow::apply(std::span<const double> u, std::span<double> v, double h, Sweep order) {
  if (order == Sweep::even_first) return sweep(u, v, h, {std::size_t{0}, std::size_t{1}}, {1.0, 1.0});
  return sweep(u, v, h, {std::size_t{1}, std::size_t{0}}, {1.0, 1.0});
}

double DampingFlow::sweep(std::span<const double> u, std::span<double> v, double h,
                          std::initializer_list<std::size_t> parities, std::initializer_list<double> fractions) {
  const std::size_t n = v.size();
  const double before = twice_kinetic(mass_.data(), v.data(), n);
  if (damping_.kk_gamma > 0) {
    prepare(h);
    std::copy(v.begin(), v.end(), vp_.begin() + 1);
    const double* fraction = fractions.begin();
    for (const std::size_t parity : parities) {
      for (std::size_t k = 0; k <= n; ++k) {
        const double x = (k > 0 ? u[k - 1] : 0.0) - (k < n ? u[k] : 0.0);
        loss_[k] = *fraction * rate_[k] * std::sqrt(std::max(overlap_[k] + x, 0.0));
      }
      pair_losses(loss_.data(), nullptr, 0, n + 1);
      pair_damping(vp_.data(), pair_share(parity), loss_.data(), 0, n + 1, parity);
      ++fraction;
    }
    std::copy(vp_.begin() + 1, vp_.begin() + 1 + static_cast<std::ptrdiff_t>(n), v.begin());
  }
  if (damping_.time > 0) scale(v.data(), n, std::exp(-h / damping_.time));
  const double after = twice_kinetic(mass_.data(), v.data(), n);
  return 0.5 * (before - after);
}

namespace {

// The kernels of a step boundary, on index ranges [lo, hi): bonds k (bond k strains
// u[k] − u[k+1]) or padded bead positions p (bead p − 1).

// The bond pass at fixed positions: the forces and stiffnesses for the corrector, and the pair
// losses of the contact damping (loss2 = 1 − q², two pair steps). For Hertz the damping's
// [δ]_+^{1/2} is the one in the stiffness K = (3/2) A [δ]_+^{1/2}: one square root per bond
// serves both (`rate` is then DampingFlow::rate_per_stiffness()).
// −2y of bond k at strain x, e^{−2y} its pair flow's factor: y = rate · K for Hertz (the stiffness
// just computed), else rate · [δ]_+^{1/2}.
template <bool hertz>
inline double pair_exponent(const double* __restrict rate, const double* __restrict stiff,
                            const double* __restrict overlap, std::size_t k, double x) {
  if constexpr (hertz) return -2 * (rate[k] * stiff[k]);
  else return -2 * (rate[k] * std::sqrt(std::max(overlap[k] + x, 0.0)));
}

template <bool corrector, bool contact, class View>
void boundary_bonds([[maybe_unused]] const View law, const double* __restrict u, [[maybe_unused]] double* __restrict f,
                    [[maybe_unused]] double* __restrict stiff, [[maybe_unused]] double* __restrict loss,
                    [[maybe_unused]] double* __restrict loss2, [[maybe_unused]] const double* __restrict rate,
                    [[maybe_unused]] const double* __restrict overlap, std::size_t lo, std::size_t hi) {
  constexpr bool hertz = std::is_same_v<View, HertzLaw::View>;
  // The losses by the short series of e^x − 1 in the same pass, and again by the longer one (or
  // the whole formula) in a block with a contact past its domain (the rule of
  // detail::expm1_nonpositive's array form).
  unsigned beyond_small = 0, beyond_unreduced = 0;  // integer ORs, which GCC vectorizes (a bool AND it does not)
  for (std::size_t k = lo; k < hi; ++k) {
    const double x = u[k] - u[k + 1];
    if constexpr (corrector || (contact && hertz)) law.force_stiffness(k, x, f[k], stiff[k]);
    if constexpr (contact) {
      const double a = pair_exponent<hertz>(rate, stiff, overlap, k, x);
      beyond_small |= a >= detail::expm1_small_bound ? 0u : 1u;
      beyond_unreduced |= a >= detail::expm1_unreduced_bound ? 0u : 1u;
      const double l = -detail::expm1_small_nonpositive(a);
      loss[k] = l;
      loss2[k] = l * (2 - l);
    }
  }
  if constexpr (contact) {
    if (beyond_small != 0 && beyond_unreduced == 0)
      for (std::size_t k = lo; k < hi; ++k) {
        const double a = pair_exponent<hertz>(rate, stiff, overlap, k, u[k] - u[k + 1]);
        const double l = -detail::expm1_unreduced_nonpositive(a);
        loss[k] = l;
        loss2[k] = l * (2 - l);
      }
    else if (beyond_unreduced != 0)
      for (std::size_t k = lo; k < hi; ++k) {
        const double l = -detail::expm1_nonpositive(pair_exponent<hertz>(rate, stiff, overlap, k, u[k] - u[k + 1]));
        loss[k] = l;
        loss2[k] = l * (2 - l);
      }
  }
}

// a_p = F/m of bead p − 1 (padded: a[0] = a[n+1] = 0 stay untouched, the walls). On-site springs
// (`ks`, null when the chain has none; `qs`, their quartic part, null when linear) add −k u − q u³
// to F, as in detail::correct_and_drift.
void accelerations(const double* __restrict f, double* __restrict a, const double* __restrict im,
                   const double* __restrict ks, const double* __restrict qs, const double* __restrict u, std::size_t lo,
                   std::size_t hi) {
  if (qs)
    for (std::size_t p = lo; p < hi; ++p)
      a[p] = im[p - 1] * (f[p - 1] - f[p] - onsite_restoring<true>(ks, qs, p - 1, u[p]));
  else if (ks)
    for (std::size_t p = lo; p < hi; ++p) a[p] = im[p - 1] * (f[p - 1] - f[p] - ks[p - 1] * u[p]);
  else
    for (std::size_t p = lo; p < hi; ++p) a[p] = im[p - 1] * (f[p - 1] - f[p]);
}

// The corrector's velocity change c (1/m) [K_{p−1} (a_{p−1} − a_p) − K_p (a_p − a_{p+1})] of bead
// p − 1 (docs/physics.md, "Nonlinear dynamics"; the expression of detail::correct_and_drift), with
// − k a_p from on-site springs (their −k on the Hessian's diagonal; − (k + 3 q u²) a_p with a
// quartic part, at the positions u the bonds saw).
void corrector_change(const double* __restrict stiff, const double* __restrict a, double* __restrict dv,
                      const double* __restrict im, const double* __restrict ks, const double* __restrict qs,
                      const double* __restrict u, std::size_t lo, std::size_t hi, double c) {
  if (qs)
    for (std::size_t p = lo; p < hi; ++p)
      dv[p] = c * im[p - 1] *
              (stiff[p - 1] * (a[p - 1] - a[p]) - stiff[p] * (a[p] - a[p + 1]) -
               onsite_hessian<true>(ks, qs, p - 1, u[p]) * a[p]);
  else if (ks)
    for (std::size_t p = lo; p < hi; ++p)
      dv[p] = c * im[p - 1] * (stiff[p - 1] * (a[p - 1] - a[p]) - stiff[p] * (a[p] - a[p + 1]) - ks[p - 1] * a[p]);
  else
    for (std::size_t p = lo; p < hi; ++p)
      dv[p] = c * im[p - 1] * (stiff[p - 1] * (a[p - 1] - a[p]) - stiff[p] * (a[p] - a[p + 1]));
}

void scale(double* __restrict v, std::size_t lo, std::size_t hi, double factor) {
  for (std::size_t p = lo; p < hi; ++p) v[p] *= factor;
}

constexpr std::size_t boundary_block = 512;

template <BondForceLaw Law>
class DampedPropagator final : public Propagator {
 public:
  DampedPropagator(const Law& law, const Chain& chain, const SplittingScheme& scheme, double tau, const State& initial,
                   const Damping& damping)
      : law_(law), scheme_(scheme), tau_(tau), n_(chain.size()), flow_(chain, damping), mass_(chain.mass) {
    up_.assign(n_ + 2, 0.0);
    vp_.assign(n_ + 2, 0.0);
    std::copy(initial.u.begin(), initial.u.end(), up_.begin() + 1);
    std::copy(initial.v.begin(), initial.v.end(), vp_.begin() + 1);
    im_ = chain.inverse_mass;
    for (auto* a : {&f_, &stiff_, &loss_, &loss2_}) a->assign(n_ + 1, 0.0);
    ap_.assign(n_ + 2, 0.0);
    dv_.assign(n_ + 2, 0.0);
    flow_.prepare(0.5 * tau);
    onsite_ = damping.time > 0 ? std::exp(-0.5 * tau / damping.time) : 1.0;
  }

  void advance(std::size_t steps) override {
    if (steps == 0) return;
    const double g = scheme_.corrector * tau_ * tau_ * tau_;
    const auto& a = scheme_.drift;
    const auto& b = scheme_.kick;
    boundary(false, true, g);
    for (std::size_t step = 0; step < steps; ++step) {
      for (std::size_t j = 0; j < b.size(); ++j)
        detail::kick_and_drift(law_.view(), up_.data(), f_.data(), vp_.data() + 1, im_.data(), 0, n_, b[j] * tau_,
                               a[j + 1] * tau_);
      boundary(true, step + 1 < steps, g);
    }
    steps_ += steps;
    bond_updates_ += steps * b.size() * (n_ + 1);
  }

  std::span<const double> displacement() const override { return {up_.data() + 1, n_}; }
  std::span<const double> velocity() const override { return {vp_.data() + 1, n_}; }
  double time_step() const override { return tau_; }
  std::uint64_t steps_done() const override { return steps_; }
  std::uint64_t bond_updates() const override { return bond_updates_; }
  double dissipated_energy() const override { return dissipated_; }

 private:
  // At fixed positions: [end: corrector g, O_{τ/2} E_{τ/2}] [start: E_{τ/2} O_{τ/2}, corrector g,
  // drift a_0 τ], with the on-site flow over τ/2 per half.
  //
  // One pass over the chain in blocks whose arrays stay in L1, as the conservative kernels: each
  // stage runs `lag` indices behind the stage before it, far enough that the neighbours it
  // reads are final (a corrector change needs a_{p±1}; a pair step needs both beads from the
  // stage before; the drift needs the bonds of both sides evaluated). Every index sees the
  // same arithmetic in the same order as stage-by-stage whole-chain loops would apply.
  void boundary(bool end, bool start, double g) {
    constexpr bool hertz = std::is_same_v<Law, HertzLaw>;
    const bool contact = flow_.damping().kk_gamma > 0, twice = end && start;
    const auto view = law_.view();
    const double* rate = hertz ? flow_.rate_per_stiffness() : flow_.rate();
    double* u = up_.data();
    double* v = vp_.data();
    double* dv = dv_.data();
    // The pair sweeps: end of a step O_{τ/2} E_{τ/2}, start E_{τ/2} O_{τ/2}, both: O_{τ/2} E_τ O_{τ/2}
    // (E_τ as two exact pair steps of τ/2, loss2).
    const std::size_t n = n_, pairs = contact ? (twice ? 3 : 2) : 0;
    const std::size_t final_lag = 2 + pairs;
    const std::size_t parity[3] = {end ? std::size_t{1} : std::size_t{0}, end ? std::size_t{0} : std::size_t{1}, 1};
    const double* loss[3] = {loss_.data(), twice ? loss2_.data() : loss_.data(), loss_.data()};
    const double d = scheme_.drift[0] * tau_;
    double before = 0, after = 0;
    for (std::size_t lo = 0;; lo += boundary_block) {
      const std::size_t hi = std::min(lo + boundary_block, n + 1);
      const bool last = hi == n + 1;
      // [lo − lag, hi − lag) clipped to [first, n], the last block to the end.
      const auto range = [&](std::size_t lag, std::size_t first) {
        const std::size_t b = std::max(lo > lag ? lo - lag : std::size_t{0}, first);
        const std::size_t e = last ? n + 1 : (hi > lag ? hi - lag : std::size_t{0});
        return std::pair{b, std::max(b, e)};
      };
      if (g != 0 || contact) {
        const auto [b, e] = range(0, 0);
        if (g != 0 && contact)
          boundary_bonds<true, true>(view, u, f_.data(), stiff_.data(), loss_.data(), loss2_.data(), rate,
                                     flow_.overlap(), b, e);
        else if (g != 0)
          boundary_bonds<true, false>(view, u, f_.data(), stiff_.data(), loss_.data(), loss2_.data(), rate,
                                      flow_.overlap(), b, e);
        else
          boundary_bonds<false, true>(view, u, f_.data(), stiff_.data(), loss_.data(), loss2_.data(), rate,
                                      flow_.overlap(), b, e);
      }
      if (g != 0) {
        const auto [b0, e0] = range(0, 1);
        accelerations(f_.data(), ap_.data(), im_.data(), view.onsite, view.onsite_quartic, u, b0, e0);
        const auto [b1, e1] = range(1, 1);
        corrector_change(stiff_.data(), ap_.data(), dv, im_.data(), view.onsite, view.onsite_quartic, u, b1, e1, g);
      }
      {
        const auto [b, e] = range(1, 1);
        double* __restrict vb = v + b;
        const double* __restrict dvb = dv + b;
        if (g != 0 && end)  // the end of a step's corrector, then the kinetic energy before the damping
          before += twice_kinetic(
              mass_.data() + b - 1, vb, e - b, [=](std::size_t i) { vb[i] += dvb[i]; }, nothing);
        else before += twice_kinetic(mass_.data() + b - 1, vb, e - b);
      }
      for (std::size_t s = 0; s < pairs; ++s) {
        const auto [b, e] = range(2 + s, 0);
        pair_damping(v, flow_.pair_share(parity[s]), loss[s], b, e, parity[s]);
      }
      {
        const auto [b, e] = range(final_lag, 1);
        if (onsite_ != 1.0) scale(v, b, e, twice ? onsite_ * onsite_ : onsite_);
        double* __restrict vb = v + b;
        double* __restrict ub = u + b;
        const double* __restrict dvb = dv + b;
        const double* mb = mass_.data() + b - 1;
        // The kinetic energy after the damping, then the next step's corrector and first drift.
        if (start && g != 0)
          after += twice_kinetic(mb, vb, e - b, nothing, [=](std::size_t i) {
            vb[i] += dvb[i];
            ub[i] += d * vb[i];
          });
        else if (start) after += twice_kinetic(mb, vb, e - b, nothing, [=](std::size_t i) { ub[i] += d * vb[i]; });
        else after += twice_kinetic(mb, vb, e - b);
      }
      if (last) break;
    }
    if (g != 0) bond_updates_ += n + 1;
    dissipated_ += 0.5 * (before - after);
  }

  Law law_;
  SplittingScheme scheme_;
  double tau_;
  std::size_t n_;
  DampingFlow flow_;
  std::vector<double> mass_, up_, vp_, im_, f_, stiff_, ap_, dv_, loss_, loss2_;
  double onsite_ = 1;
  std::uint64_t steps_ = 0, bond_updates_ = 0;
  double dissipated_ = 0;
};

}  // namespace

std::unique_ptr<Propagator> make_damped_propagator(const ForceLaw& law, const Chain& chain,
                                                   const SplittingScheme& scheme, double time_step,
                                                   const State& initial, const Damping& damping) {
  validate_propagation(chain, time_step, initial);
  validate(damping);
  if (damping.kk_gamma > 0 && !chain.spring.empty())
    throw InvalidInput("kk_gamma", ": contact damping needs contacts; the chain's bonds are linear springs");
  if (!damping.any()) return make_splitting_propagator(law, chain, scheme, time_step, initial, ActiveWindow{false});
  return std::visit(
      [&](const auto& l) -> std::unique_ptr<Propagator> {
        using Law = std::decay_t<decltype(l)>;
        return std::make_unique<DampedPropagator<Law>>(l, chain, scheme, time_step, initial, damping);
      },
      law);
}

}  // namespace granular
