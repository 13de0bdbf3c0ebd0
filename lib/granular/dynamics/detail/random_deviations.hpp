#pragma once
// The random starting deviation vectors of the Lyapunov spectrum and of the alignment indices
// (lyapunov_spectrum.hpp, alignment_indices.hpp), one generator so that the same seed starts both
// from the same vectors.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "granular/dynamics/state.hpp"

namespace granular::detail {

/// k vectors of N beads from `seed` (splitmix64, δu and t_unit δv uniform in (−1, 1)): generic
/// directions, the same on every machine; not orthonormal (the callers' Householder QR makes them so).
std::vector<State> random_deviation_vectors(std::size_t beads, std::size_t k, std::uint64_t seed, double time_unit);

}  // namespace granular::detail
