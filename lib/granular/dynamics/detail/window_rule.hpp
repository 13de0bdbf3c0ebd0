#pragma once
// The active window's rule (propagator.hpp, ActiveWindow), written once for the one-chain stepper
// and the lanes: where it opens on the initial state, which beads are its edges, how far it grows.
#include <algorithm>
#include <cstddef>
#include <utility>

#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/state.hpp"

namespace granular::detail {

/// [lo, hi): the non-zero part of `initial` widened by the guard on each side; the whole chain
/// when the window is off, has no guard, or the state is zero.
inline std::pair<std::size_t, std::size_t> opened_window(const State& initial, const ActiveWindow& window) {
  const std::size_t n = initial.u.size();
  if (!window.enabled || window.guard == 0) return {0, n};
  std::size_t first = n, last = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (initial.u[i] != 0 || initial.v[i] != 0) {
      first = std::min(first, i);
      last = i;
    }
  if (first == n) return {0, n};
  return {first > window.guard ? first - window.guard : 0, std::min(n, last + 1 + window.guard)};
}

/// The beads whose kinetic energy is checked after a step: the left edge's (while lo > 0; else
/// empty), then the right edge's from the left edge as it stands after that check (while hi < n).
inline std::pair<std::size_t, std::size_t> left_edge(std::size_t lo, std::size_t hi, std::size_t guard) {
  return lo > 0 ? std::pair{lo, std::min(lo + guard, hi)} : std::pair{lo, lo};
}
inline std::pair<std::size_t, std::size_t> right_edge(std::size_t lo, std::size_t hi, std::size_t n, std::size_t guard) {
  return hi < n ? std::pair{hi > lo + guard ? hi - guard : lo, hi} : std::pair{hi, hi};
}
/// Whether a bead of velocity v and inverse mass im disturbs the window: m v²/2 > θ H0, compared as
/// v² > limit · (1/m) with limit = 2 θ H0 (no division per bead). For a double or a lane vector.
template <class T>
inline auto disturbs(const T& v, const T& limit, const T& im) {
  return v * v > limit * im;
}

/// The window's edges once a disturbed edge has grown by the guard.
inline std::size_t grown_lo(std::size_t lo, std::size_t guard) { return lo > guard ? lo - guard : 0; }
inline std::size_t grown_hi(std::size_t hi, std::size_t n, std::size_t guard) { return std::min(n, hi + guard); }

}  // namespace granular::detail
