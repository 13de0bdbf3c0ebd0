#pragma once
// The phase-space state of a chain: displacements from the precompressed equilibrium and
// velocities, one entry per bead (0-based), walls excluded (they never move).
#include <cstddef>
#include <vector>

namespace granular {

struct State {
  std::vector<double> u;  ///< displacements u_n [m]
  std::vector<double> v;  ///< velocities du_n/dt [m/s]

  State() = default;
  explicit State(std::size_t n) : u(n, 0.0), v(n, 0.0) {}
  std::size_t size() const { return u.size(); }
};

}  // namespace granular
