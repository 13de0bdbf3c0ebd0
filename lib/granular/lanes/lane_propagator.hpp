#pragma once
// Several chains of one length stepped side by side, one per vector lane: the splitting scheme of
// make_splitting_propagator (propagator.hpp) on up to width() realizations at once, each lane
// with its own chain, initial state and active window. Every lane's state is, bit for bit, what
// the one-chain propagator gives its chain after the same steps; the lanes only share the loop
// (an ensemble's realizations run width() at a time for the cost of about one).
//
//   std::vector<granular::ForceLaw> laws;  // one per chain, of one kind
//   granular::LanePropagator lanes(laws, chains, granular::saba2c(), 1e-7, initials);
//   lanes.advance(1000);
//   std::vector<double> u, v;
//   lanes.copy_lane(2, u, v);  // the third chain at t = 1000 τ
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/dynamics/state.hpp"
#include "granular/model/chain.hpp"

namespace granular {

namespace detail {
struct LaneChains;  // the chains interleaved (detail/lane_chains.hpp)
}

class LanePropagator {
 public:
  /// The lanes of this build's CPU vectors: 8 with AVX-512, 4 with AVX, else 2.
  static std::size_t width();

  /// Lane l integrates chains[l] under laws[l] (make_force_law of one kind for every chain) from
  /// initials[l], for l < chains.size() ≤ width(); every chain has the same length. Throws
  /// InvalidInput as make_splitting_propagator does, and for chains of other lengths or laws of
  /// other kinds.
  LanePropagator(std::span<const ForceLaw> laws, std::span<const Chain> chains, const SplittingScheme& scheme,
                 double time_step, std::span<const State> initials, const ActiveWindow& window = {});

  /// Advances every lane by `steps` × τ.
  void advance(std::size_t steps);

  ~LanePropagator();
  LanePropagator(LanePropagator&&) noexcept;
  LanePropagator& operator=(LanePropagator&&) noexcept;

  std::size_t lanes() const { return lanes_; }
  std::size_t beads() const { return n_; }
  std::uint64_t steps_done() const { return steps_; }
  /// Lane l's displacements [m] and velocities [m/s] now, into u and v (resized to the length).
  void copy_lane(std::size_t lane, std::vector<double>& u, std::vector<double>& v) const;
  /// copy_lane for vectors that hold an earlier copy of the same lane: only the window is written
  /// (beads outside it were at rest then too, as a window only grows). What a driver sampling
  /// often uses.
  void refresh_lane(std::size_t lane, std::vector<double>& u, std::vector<double>& v) const;
  /// Lane l's active window: beads outside [window_begin, window_end) are exactly at rest.
  std::size_t window_begin(std::size_t lane) const { return lo_[lane]; }
  std::size_t window_end(std::size_t lane) const { return hi_[lane]; }
  /// Lane l's bond force evaluations so far, counted as its own propagator would count them.
  std::uint64_t bond_updates(std::size_t lane) const { return bond_updates_[lane]; }

 private:
  /// A kick (v += h F/m) or, with `corrector`, the corrector of weight `weight`; then u += d v.
  void pass(bool corrector, double weight, double d);
  void drift(double d);
  void count_updates();
  void grow_windows();
  bool disturbed(std::size_t lane, std::size_t begin, std::size_t end) const;

  SplittingScheme scheme_;
  double tau_;
  ActiveWindow window_;
  std::unique_ptr<detail::LaneChains> c_;  // the chains, their laws and states, interleaved
  std::size_t n_ = 0, lanes_ = 0;
  std::vector<std::size_t> lo_, hi_;  // per lane
  std::vector<double> kinetic_limit_;
  std::size_t union_lo_ = 0, union_hi_ = 0;
  std::vector<std::uint64_t> bond_updates_;
  std::uint64_t steps_ = 0;
};

}  // namespace granular
