#pragma once
// How long an IPR map of every mode will take, said before it starts: each of its chains is one
// solve of every mode (O(N²) time, O(N) memory by the fast solver), and a map of long chains runs
// minutes to days with its progress counted in chains. One chain of the map is timed on its
// leading beads (study/solve_estimate.hpp) and scaled by the chains over the threads.
#include <cstddef>
#include <string>

#include "granular/study/ipr_map.hpp"
#include "granular/study/solve_estimate.hpp"

namespace granular {

struct IprMapEstimate {
  SolveEstimate chain;     ///< one chain of the map (its first cell's first realization)
  std::size_t chains = 0;  ///< cells × realizations
  int threads = 1;         ///< chains solved at once
  double seconds = 0;      ///< chain.seconds · ⌈chains / threads⌉ [s]; 0 when nothing was estimated
};

/// The estimate for `config` on `threads` threads (≥ 1); nothing (seconds 0) for a selection or
/// chains short enough not to need one (estimate_every_mode_solve). Call after validate(config).
IprMapEstimate estimate_ipr_map(const IprMapConfig& config, int threads);

/// One line for stderr, e.g. "4 chains of 20000 beads, every mode: about 21 s on 2 threads (one chain:
/// about 10 s; 1000 beads took 0.05 s, time grows as N^2.2 here); progress counts chains".
std::string describe(const IprMapEstimate& estimate);

}  // namespace granular
