#pragma once
// The spread over realizations of a statistic of an ensemble mean — what a second ensemble of
// the same size would give — by the bootstrap: draw R realizations with replacement from the R
// at hand (whole realizations, so each keeps its own curve), average their series, compute the
// statistic, repeat; the standard deviation over the resamples estimates the statistic's
// standard error. It complements the sub-window spread of a fit, which says nothing about how
// many realizations were averaged.
//
// Deterministic: resample b draws its R indices from Philox4x64 keyed by (seed, b) and sums the
// chosen rows in index order, so the answer is the same for any thread count.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace granular {

struct BootstrapConfig {
  std::size_t resamples = 1000;
  std::uint64_t seed = 0x626f6f74;  ///< "boot": a key of its own, apart from the chains' (seed, r)
  int threads = 0;                  ///< 0 = every core; the result does not depend on it
};

/// `rows` holds R realizations' series of `width` values each, row-major (row r at r·width).
/// `statistics(mean)` maps a mean series (width values) to k numbers. Returns, for each of the
/// k, the sample standard deviation over `config.resamples` (≥ 2) resamples. A statistic that
/// throws on a resample propagates the exception. Throws InvalidInput on an empty or ragged
/// `rows` or fewer than 2 resamples.
std::vector<double> bootstrap_standard_deviation(
    std::span<const double> rows, std::size_t width,
    const std::function<std::vector<double>(const std::vector<double>& mean)>& statistics,
    const BootstrapConfig& config);

}  // namespace granular
