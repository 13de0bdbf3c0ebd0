// The reference integrator: Boost.Odeint's controlled Runge–Kutta–Fehlberg 7(8) at tight
// tolerances, on the same force law. Not symplectic and slow; it exists to check the others.
#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/numeric/odeint.hpp>

#include "granular/dynamics/propagator.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

namespace odeint = boost::numeric::odeint;
using Vector = std::vector<double>;

// y = [u/ℓ, v·t_s/ℓ]: both halves O(1), so one absolute tolerance fits both.
constexpr double time_unit = 1e-6;

template <BondForceLaw Law>
struct ScaledChain {
  const Law* law;
  const double* inverse_mass;
  std::size_t n;
  double length;
  Vector* forces;
  std::uint64_t* bond_updates;

  void operator()(const Vector& y, Vector& dydt, double /*t*/) const {
    const auto l = law->view();
    const double* __restrict q = y.data();
    const double* __restrict w = y.data() + n;
    double* __restrict dq = dydt.data();
    double* __restrict dw = dydt.data() + n;
    double* __restrict f = forces->data();
    const double* __restrict im = inverse_mass;
    for (std::size_t i = 0; i < n; ++i) dq[i] = w[i] / time_unit;
    f[0] = l.force(0, -length * q[0]);
    for (std::size_t k = 1; k < n; ++k) f[k] = l.force(k, length * (q[k - 1] - q[k]));
    f[n] = l.force(n, length * q[n - 1]);
    const double scale = time_unit / length;
    for (std::size_t i = 0; i < n; ++i) dw[i] = scale * im[i] * (f[i] - f[i + 1]);
    if (l.onsite_quartic)  // the on-site springs' −k u − q u³
      for (std::size_t i = 0; i < n; ++i)
        dw[i] -= scale * im[i] * onsite_restoring<true>(l.onsite, l.onsite_quartic, i, length * q[i]);
    else if (l.onsite)  // the on-site springs' −k u
      for (std::size_t i = 0; i < n; ++i) dw[i] -= scale * im[i] * l.onsite[i] * length * q[i];
    *bond_updates += n + 1;
  }
};

template <BondForceLaw Law>
class ReferencePropagator final : public Propagator {
 public:
  ReferencePropagator(const Law& law, const Chain& chain, double tau, const State& initial,
                      const ReferenceTolerance& tolerance)
      : law_(law), im_(chain.inverse_mass), n_(chain.size()), tau_(tau),
        stepper_(odeint::make_controlled(tolerance.absolute, tolerance.relative, tolerance.max_step,
                                         odeint::runge_kutta_fehlberg78<Vector>())) {
    double amplitude = 0;
    for (std::size_t i = 0; i < n_; ++i)
      amplitude = std::max({amplitude, std::abs(initial.u[i]), std::abs(initial.v[i]) * time_unit});
    length_ = amplitude > 0 ? amplitude : 1.0;
    y_.resize(2 * n_);
    for (std::size_t i = 0; i < n_; ++i) {
      y_[i] = initial.u[i] / length_;
      y_[n_ + i] = initial.v[i] * time_unit / length_;
    }
    forces_.assign(n_ + 1, 0.0);
    u_.assign(initial.u.begin(), initial.u.end());
    v_.assign(initial.v.begin(), initial.v.end());
    dt_ = tau / 4;
  }

  void advance(std::size_t steps) override {
    ScaledChain<Law> system{&law_, im_.data(), n_, length_, &forces_, &bond_updates_};
    const double t_end = static_cast<double>(steps_ + steps) * tau_;
    std::size_t attempts = 0;
    while (t_ < t_end) {
      const bool last = t_ + dt_ >= t_end;
      double dt = last ? t_end - t_ : dt_;
      const auto result = stepper_.try_step(system, y_, t_, dt);
      if (result == odeint::success) {
        if (last) t_ = t_end;  // land exactly, whatever the rounding of t + dt
        // Keep the step the controller proposes, unless it only shrank because we clipped it.
        if (!last || dt > dt_) dt_ = dt;
      } else {
        dt_ = dt;
        if (++attempts > 1000000 || !(dt_ > 1e-12 * tau_))
          throw NumericalError("reference integrator: step size collapsed at t = " + std::to_string(t_) + " s");
      }
    }
    steps_ += steps;
    for (std::size_t i = 0; i < n_; ++i) {
      u_[i] = y_[i] * length_;
      v_[i] = y_[n_ + i] * length_ / time_unit;
    }
  }

  std::span<const double> displacement() const override { return u_; }
  std::span<const double> velocity() const override { return v_; }
  double time_step() const override { return tau_; }
  std::uint64_t steps_done() const override { return steps_; }
  std::uint64_t bond_updates() const override { return bond_updates_; }

 private:
  Law law_;
  std::vector<double> im_;
  std::size_t n_;
  double tau_, length_ = 1, t_ = 0, dt_;
  decltype(odeint::make_controlled(1.0, 1.0, 1.0, odeint::runge_kutta_fehlberg78<Vector>())) stepper_;
  Vector y_, forces_, u_, v_;
  std::uint64_t steps_ = 0, bond_updates_ = 0;
};

}  // namespace

std::unique_ptr<Propagator> make_reference_propagator(const ForceLaw& law, const Chain& chain, double time_step,
                                                      const State& initial, const ReferenceTolerance& tolerance) {
  validate_propagation(chain, time_step, initial);
  if (!(tolerance.absolute > 0) || !(tolerance.relative >= 0) || !(tolerance.max_step >= 0))
    throw InvalidInput("reference tolerances must be > 0");
  return std::visit(
      [&](const auto& l) -> std::unique_ptr<Propagator> {
        using Law = std::decay_t<decltype(l)>;
        return std::make_unique<ReferencePropagator<Law>>(l, chain, time_step, initial, tolerance);
      },
      law);
}

}  // namespace granular
