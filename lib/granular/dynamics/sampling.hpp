#pragma once
// When a run looks at the chain: sample steps, all whole multiples of τ, so that every
// integrator samples at the same times (docs/physics.md, "Nonlinear dynamics"). Observers (observers.hpp) build their
// schedules from these.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace granular {

enum class Sampling { logarithmic, uniform };
Sampling parse_sampling(const std::string& name);  ///< "log" | "uniform"
std::string to_string(Sampling sampling);          ///< "log" | "uniform"

/// Step numbers of `count` log-spaced (1 … total, duplicates removed) or uniform
/// (0, stride, 2·stride …, stride = ⌊total/(count−1)⌋) samples.
std::vector<std::uint64_t> sample_steps(std::uint64_t total, std::size_t count, Sampling sampling);

/// A uniform grid of sample times, [begin, end] every `step` (all multiples of τ): where the
/// exponents are fitted and L_d is taken, so that they see the curve densely (the paper
/// computes L_d "where we discretize time as in our numerical integration"). Empty when
/// end ≤ begin.
struct DenseGrid {
  double begin = 0, end = 0;  ///< [s]
  double step = 1e-5;         ///< [s], a whole number of time steps
  bool empty() const { return !(end > begin); }
};

/// `steps` (sorted) with those inside `grid` replaced by the grid's own steps (begin,
/// begin + step, …, and end, clipped to `total`); sorted, without duplicates.
std::vector<std::uint64_t> with_dense_grid(std::vector<std::uint64_t> steps, const DenseGrid& grid, std::uint64_t total,
                                           double time_step);

}  // namespace granular
