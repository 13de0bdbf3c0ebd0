#pragma once
// W chains of one length and their force laws, interleaved for the lane kernels (lane_kernels.hpp,
// lane_tangent_kernels.hpp): what LanePropagator and LaneTangentPropagator both start from.
// Element i of lane l sits at [i · W + l].
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/dynamics/state.hpp"
#include "granular/model/chain.hpp"

namespace granular::detail {

struct LaneChains {
  std::size_t n = 0;      ///< beads of every chain
  std::size_t lanes = 0;  ///< chains given (≤ W); the other lanes idle
  bool hertz = true, grounded = false, quartic = false;
  // u padded with the walls (row i + 1 is bead i), v and 1/m per bead, the law's three coefficients
  // per bond (Hertz: contact, overlap, rest; polynomial: c1, c2, c3), on-site k and q per bead
  // (empty when the law has none). Idle lanes carry lane 0's coefficients at rest: finite numbers,
  // every force 0.
  std::vector<double> u, v, im, p1, p2, p3, k, q;
};

/// Lane l holds chains[l] under laws[l] from initials[l], for l < chains.size() ≤ `width`. Throws
/// InvalidInput as make_splitting_propagator does, and for chains of other lengths, laws of other
/// kinds or more chains than lanes.
LaneChains interleave(std::span<const ForceLaw> laws, std::span<const Chain> chains, const SplittingScheme& scheme,
                      double time_step, std::span<const State> initials, std::size_t width);

/// Lane `lane` of `values` (one per bead, N of them) written into the interleaved `to`, its row i
/// at i + `pad` (1: the padded u).
void put_lane(std::vector<double>& to, std::size_t lane, std::span<const double> values, std::size_t pad,
              std::size_t width);

/// Rows [begin, end) of lane `lane` of the interleaved `from` (row i at i + `pad`) into to[begin, end):
/// put_lane's inverse.
void take_lane(const std::vector<double>& from, std::size_t lane, std::size_t pad, std::size_t width,
               std::vector<double>& to, std::size_t begin, std::size_t end);

/// Throws InvalidInput("lane") unless `lane` holds one of the chains.
void check_lane(const LaneChains& c, std::size_t lane);

/// Calls `run(hertz, grounded, quartic)` with the three as compile-time constants
/// (std::true_type / std::false_type).
template <class Run>
void with_kernel(const LaneChains& c, Run&& run) {
  const auto on = [&](auto h) {
    if (c.quartic) run(h, std::true_type{}, std::true_type{});
    else if (c.grounded) run(h, std::true_type{}, std::false_type{});
    else run(h, std::false_type{}, std::false_type{});
  };
  if (c.hertz) on(std::true_type{});
  else on(std::false_type{});
}

}  // namespace granular::detail
