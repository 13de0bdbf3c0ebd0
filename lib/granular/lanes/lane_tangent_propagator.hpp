#pragma once
// The tangent map (tangent_map.hpp) on several chains side by side, one per vector lane
// (lane_propagator.hpp): up to width() orbits of one length, each carrying its one deviation
// vector, for the maximal Lyapunov exponents of an ensemble. Every lane's orbit, deviation vector
// and log-stretch are, bit for bit, what its chain's own TangentPropagator gives after the same
// steps; a lane whose deviation vector becomes zero or non-finite stops renormalizing and says so
// (failure()), the others go on.
//
//   granular::LaneTangentPropagator lanes(laws, chains, granular::saba2c(), 1e-7, initials, deviations,
//                                         {.enabled = true, .renormalize_every = 10});
//   lanes.advance(100000);
//   double x1 = lanes.log_stretch(3) / (100000 * 1e-7);  // the fourth chain's X1(t) [1/s]
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/dynamics/state.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/model/chain.hpp"

namespace granular {

namespace detail {
struct LaneChains;  // the chains interleaved (detail/lane_chains.hpp)
}

class LaneTangentPropagator {
 public:
  /// The lanes of this build's CPU vectors (LanePropagator::width()).
  static std::size_t width();

  /// Lane l integrates chains[l] under laws[l] from initials[l] with the deviation vector
  /// deviations[l], for l < chains.size() ≤ width(), every chain of one length; renormalized as
  /// `config` says (LyapunovConfig: every renormalize_every steps, norm with time_unit). Throws
  /// InvalidInput as make_tangent_propagator does (a deviation vector zero or non-finite, naming
  /// `deviation`) and as LanePropagator does.
  LaneTangentPropagator(std::span<const ForceLaw> laws, std::span<const Chain> chains, const SplittingScheme& scheme,
                        double time_step, std::span<const State> initials, std::span<const State> deviations,
                        const LyapunovConfig& config);

  /// Advances every lane by `steps` × τ.
  void advance(std::size_t steps);

  ~LaneTangentPropagator();
  LaneTangentPropagator(LaneTangentPropagator&&) noexcept;
  LaneTangentPropagator& operator=(LaneTangentPropagator&&) noexcept;

  std::size_t lanes() const { return lanes_; }
  std::size_t beads() const { return n_; }
  std::uint64_t steps_done() const { return steps_; }
  double time_step() const { return tau_; }
  double time_unit() const { return config_.time_unit; }
  /// Lane l's displacements [m] and velocities [m/s], into u and v (resized to the length).
  void copy_lane(std::size_t lane, std::vector<double>& u, std::vector<double>& v) const;
  /// Lane l's deviation vector now (δu, δv), into du and dv (resized to the length).
  void copy_deviation(std::size_t lane, std::vector<double>& du, std::vector<double>& dv) const;
  /// ln(‖w(t)‖/‖w(0)‖) of lane l, renormalizations included (TangentPropagator::log_stretch).
  double log_stretch(std::size_t lane) const;
  /// Lane l's bond force evaluations so far, counted as its own propagator counts them.
  std::uint64_t bond_updates(std::size_t /*lane*/) const { return bond_updates_; }
  /// Why lane l stopped ("" while it runs): its deviation vector became zero or non-finite at a
  /// renormalization, where TangentPropagator throws NumericalError with this message.
  const std::string& failure(std::size_t lane) const { return failures_[lane]; }

 private:
  void renormalize();
  double norm(std::size_t lane) const;

  SplittingScheme scheme_;
  double tau_;
  LyapunovConfig config_;
  std::unique_ptr<detail::LaneChains> c_;  // the chains, their laws and states, interleaved
  std::size_t n_ = 0, lanes_ = 0;
  std::vector<double> du_, dv_;  // interleaved as c_.u and c_.v
  std::vector<double> logs_, initial_log_norm_;
  // Every lane's ‖w‖ at step norms_step_ (the vectors change only as steps are taken).
  mutable std::vector<double> norms_;
  mutable std::uint64_t norms_step_ = static_cast<std::uint64_t>(-1);
  std::vector<std::string> failures_;
  std::uint64_t steps_ = 0, bond_updates_ = 0;
};

}  // namespace granular
