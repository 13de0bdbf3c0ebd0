#include "granular/dynamics/damping.hpp"

#include <cmath>
#include <variant>

#include "granular/dynamics/detail/plain_step.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

// Σ m v² with eight independent partial sums (a fixed order, so deterministic): a single
// accumulator would make the sum latency-bound and cost more than the damping itself.
double twice_kinetic(const double* __restrict m, const double* __restrict v, std::size_t n) {
  double part[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8)
    for (std::size_t j = 0; j < 8; ++j) part[j] += m[i + j] * v[i + j] * v[i + j];
  for (; i < n; ++i) part[0] += m[i] * v[i] * v[i];
  return ((part[0] + part[1]) + (part[2] + part[3])) + ((part[4] + part[5]) + (part[6] + part[7]));
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
  weight_.assign(n + 1, 0.0);
  diag_.assign(n, 0.0);
  upper_.assign(n, 0.0);
  rhs_.assign(n, 0.0);
}

double DampingFlow::apply(std::span<const double> u, std::span<double> v, double h) {
  const std::size_t n = v.size();
  const double before = twice_kinetic(mass_.data(), v.data(), n);
  if (damping_.kk_gamma > 0) {
    // Trapezoidal step of M v̇ = −C v: v' = v − h (M + hC/2)⁻¹ C v. With C = 0 it is v' = v exactly.
    const auto weight = [&](std::size_t k, double x) {
      return damping_.kk_gamma * contact_[k] * std::sqrt(std::max(overlap_[k] + x, 0.0));
    };
    weight_[0] = weight(0, -u[0]);
    for (std::size_t k = 1; k < n; ++k) weight_[k] = weight(k, u[k - 1] - u[k]);
    weight_[n] = weight(n, u[n - 1]);
    const double half = 0.5 * h;
    // (C v)_i = w_i (v_i − v_{i−1}) + w_{i+1} (v_i − v_{i+1}), the walls at rest; the end beads
    // apart so that the loop has no branch.
    for (std::size_t i = 0; i < n; ++i) {
      diag_[i] = mass_[i] + half * (weight_[i] + weight_[i + 1]);
      upper_[i] = -half * weight_[i + 1];  // couples i and i+1
    }
    rhs_[0] = weight_[0] * v[0] + weight_[1] * (v[0] - v[1]);
    for (std::size_t i = 1; i + 1 < n; ++i)
      rhs_[i] = weight_[i] * (v[i] - v[i - 1]) + weight_[i + 1] * (v[i] - v[i + 1]);
    rhs_[n - 1] = weight_[n - 1] * (v[n - 1] - v[n - 2]) + weight_[n] * v[n - 1];
    // Thomas algorithm (symmetric, diagonally dominant: no pivoting), with the inverse pivots
    // kept in diag_ so that one division per bead sits on the sequential recurrence.
    diag_[0] = 1 / diag_[0];
    for (std::size_t i = 1; i < n; ++i) {
      const double factor = upper_[i - 1] * diag_[i - 1];
      rhs_[i] -= factor * rhs_[i - 1];
      diag_[i] = 1 / (diag_[i] - factor * upper_[i - 1]);
    }
    rhs_[n - 1] *= diag_[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) rhs_[i] = (rhs_[i] - upper_[i] * rhs_[i + 1]) * diag_[i];
    for (std::size_t i = 0; i < n; ++i) v[i] -= h * rhs_[i];
  }
  if (damping_.time > 0) {
    const double factor = std::exp(-h / damping_.time);
    for (std::size_t i = 0; i < n; ++i) v[i] *= factor;
  }
  const double after = twice_kinetic(mass_.data(), v.data(), n);
  return 0.5 * (before - after);
}

namespace {

template <BondForceLaw Law>
class DampedPropagator final : public Propagator {
 public:
  DampedPropagator(const Law& law, const Chain& chain, const SplittingScheme& scheme, double tau, const State& initial,
                   const Damping& damping)
      : law_(law), scheme_(scheme), tau_(tau), n_(chain.size()), flow_(chain, damping) {
    up_.assign(n_ + 2, 0.0);
    std::copy(initial.u.begin(), initial.u.end(), up_.begin() + 1);
    v_ = initial.v;
    im_ = chain.inverse_mass;
    f_.assign(n_ + 1, 0.0);
    stiff_.assign(n_ + 1, 0.0);
    ap_.assign(n_ + 2, 0.0);
  }

  void advance(std::size_t steps) override {
    const detail::PlainWork work{f_.data(), stiff_.data(), ap_.data()};
    for (std::size_t s = 0; s < steps; ++s) {
      dissipated_ += flow_.apply(displacement(), v_, 0.5 * tau_);
      detail::plain_step(law_.view(), scheme_, up_.data(), v_.data(), im_.data(), n_, tau_, work);
      dissipated_ += flow_.apply(displacement(), v_, 0.5 * tau_);
    }
    steps_ += steps;
    bond_updates_ += steps * scheme_.force_evaluations_per_step() * (n_ + 1);
    if (scheme_.corrector != 0) bond_updates_ += steps * (n_ + 1);  // unmerged correctors
  }

  std::span<const double> displacement() const override { return {up_.data() + 1, n_}; }
  std::span<const double> velocity() const override { return {v_.data(), n_}; }
  double time_step() const override { return tau_; }
  std::uint64_t steps_done() const override { return steps_; }
  std::uint64_t bond_updates() const override { return bond_updates_; }
  double dissipated_energy() const override { return dissipated_; }

 private:
  Law law_;
  SplittingScheme scheme_;
  double tau_;
  std::size_t n_;
  DampingFlow flow_;
  std::vector<double> up_, v_, im_, f_, stiff_, ap_;
  std::uint64_t steps_ = 0, bond_updates_ = 0;
  double dissipated_ = 0;
};

}  // namespace

std::unique_ptr<Propagator> make_damped_propagator(const ForceLaw& law, const Chain& chain,
                                                   const SplittingScheme& scheme, double time_step,
                                                   const State& initial, const Damping& damping) {
  validate_propagation(chain, time_step, initial);
  validate(damping);
  return std::visit(
      [&](const auto& l) -> std::unique_ptr<Propagator> {
        using Law = std::decay_t<decltype(l)>;
        return std::make_unique<DampedPropagator<Law>>(l, chain, scheme, time_step, initial, damping);
      },
      law);
}

}  // namespace granular
