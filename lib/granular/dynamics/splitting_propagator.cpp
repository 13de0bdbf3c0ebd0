// The symplectic splitting stepper (docs/physics.md, "Nonlinear dynamics"): one loop runs every drift–kick scheme, with the
// SABA2C corrector when the scheme has one. Hot loops: per-bond arrays, 1/m per bead,
// branch-free [x]_+, restrict pointers, no allocation after construction.
#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "granular/dynamics/detail/blocked_kernels.hpp"
#include "granular/dynamics/detail/splitting_sequence.hpp"
#include "granular/dynamics/detail/window_rule.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/error.hpp"

namespace granular {

State Propagator::state() const {
  State s;
  const auto u = displacement();
  const auto v = velocity();
  s.u.assign(u.begin(), u.end());
  s.v.assign(v.begin(), v.end());
  return s;
}

namespace {

using detail::correct_and_drift;
using detail::drift_only;
using detail::kick_and_drift;

template <BondForceLaw Law>
class SplittingPropagator final : public Propagator {
 public:
  SplittingPropagator(const Law& law, const Chain& chain, const SplittingScheme& scheme, double tau,
                      const State& initial, const ActiveWindow& window, double initial_energy)
      : law_(law), scheme_(scheme), tau_(tau), n_(chain.size()), window_(window) {
    // Padded bead arrays: index i+1 is bead i, indices 0 and N+1 are the walls (always 0).
    up_.assign(n_ + 2, 0.0);
    ap_.assign(n_ + 2, 0.0);
    v_ = initial.v;
    im_ = chain.inverse_mass;
    std::copy(initial.u.begin(), initial.u.end(), up_.begin() + 1);
    f_.assign(n_ + 1, 0.0);
    stiff_.assign(n_ + 1, 0.0);
    std::tie(lo_, hi_) = detail::opened_window(initial, window_);
    if (window_.enabled && window_.guard > 0) {
      // Compare m v² / 2 > θ H0 as v² > 2 θ H0 / m without a division per bead.
      kinetic_limit_ = 2 * window_.threshold * initial_energy;
    }
  }

  void advance(std::size_t steps) override {
    if (steps == 0) return;
    detail::splitting_sequence(
        scheme_, tau_, steps, [&](double h, double d) { kick(h, d); }, [&](double c, double d) { correct(c, d); },
        [&](double d) { drift(d); },
        [&] {
          if (window_.enabled && (lo_ > 0 || hi_ < n_)) grow_window();
        });
    steps_ += steps;
  }

  std::span<const double> displacement() const override { return {up_.data() + 1, n_}; }
  std::span<const double> velocity() const override { return {v_.data(), n_}; }
  double time_step() const override { return tau_; }
  std::uint64_t steps_done() const override { return steps_; }
  std::size_t window_begin() const override { return lo_; }
  std::size_t window_end() const override { return hi_; }
  std::uint64_t bond_updates() const override { return bond_updates_; }

 private:
  void drift(double d) { drift_only(up_.data(), v_.data(), lo_, hi_, d); }

  void kick(double h, double d) {
    kick_and_drift(law_.view(), up_.data(), f_.data(), v_.data(), im_.data(), lo_, hi_, h, d);
    bond_updates_ += hi_ - lo_ + 1;
  }

  void correct(double c, double d) {
    correct_and_drift(law_.view(), up_.data(), f_.data(), stiff_.data(), ap_.data(), v_.data(), im_.data(), lo_, hi_, c,
                      d);
    bond_updates_ += hi_ - lo_ + 1;
  }

  bool disturbed(std::size_t begin, std::size_t end) const {
    for (std::size_t i = begin; i < end; ++i)
      if (detail::disturbs(v_[i], kinetic_limit_, im_[i])) return true;
    return false;
  }

  void grow_window() {
    const std::size_t guard = window_.guard;
    if (const auto [b, e] = detail::left_edge(lo_, hi_, guard); b < e && disturbed(b, e))
      lo_ = detail::grown_lo(lo_, guard);
    if (const auto [b, e] = detail::right_edge(lo_, hi_, n_, guard); b < e && disturbed(b, e))
      hi_ = detail::grown_hi(hi_, n_, guard);
  }

  Law law_;
  SplittingScheme scheme_;
  double tau_;
  std::size_t n_;
  ActiveWindow window_;
  std::vector<double> up_, v_, im_, f_, stiff_, ap_;
  std::size_t lo_ = 0, hi_ = 0;
  double kinetic_limit_ = 0;
  std::uint64_t steps_ = 0;
  std::uint64_t bond_updates_ = 0;
};

}  // namespace

void validate_propagation(const Chain& chain, double time_step, const State& initial) {
  if (!(time_step > 0) || !std::isfinite(time_step))
    throw InvalidInput("time_step", " " + std::to_string(time_step) + ": the time step must be finite and > 0");
  if (initial.u.size() != chain.size() || initial.v.size() != chain.size())
    throw InvalidInput("initial state has " + std::to_string(initial.u.size()) + " beads, the chain " +
                       std::to_string(chain.size()));
  for (std::size_t i = 0; i < chain.size(); ++i)
    if (!std::isfinite(initial.u[i]) || !std::isfinite(initial.v[i]))
      throw InvalidInput("initial state of bead " + std::to_string(i + 1) + " is not finite");
}

std::unique_ptr<Propagator> make_splitting_propagator(const ForceLaw& law, const Chain& chain,
                                                      const SplittingScheme& scheme, double time_step,
                                                      const State& initial, const ActiveWindow& window) {
  validate_propagation(chain, time_step, initial);
  if (scheme.drift.size() != scheme.kick.size() + 1 || scheme.kick.empty())
    throw InvalidInput("scheme " + scheme.name + ": needs s kicks and s+1 drifts");
  if (window.enabled && !(window.threshold >= 0)) throw InvalidInput("active window threshold must be >= 0");
  const double energy = window.enabled ? total_energy(law, chain, initial) : 0.0;
  return std::visit(
      [&](const auto& l) -> std::unique_ptr<Propagator> {
        using Law = std::decay_t<decltype(l)>;
        return std::make_unique<SplittingPropagator<Law>>(l, chain, scheme, time_step, initial, window, energy);
      },
      law);
}

}  // namespace granular
