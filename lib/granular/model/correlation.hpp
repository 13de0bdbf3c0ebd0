#pragma once
// Pearson correlation of a configuration with its cyclic shifts (SPEC §2, "Correlations").
#include <cstddef>
#include <vector>

#include "granular/model/disorder.hpp"

namespace granular {

/// ρ(d) for d = 0 … max_distance, with type 1 → 0 and type 2 → 1. NaN for every d when the
/// configuration has one type only (σ = 0: the coefficient is undefined).
std::vector<double> cyclic_correlation(const Configuration& types, std::size_t max_distance);

/// Infinite-chain ρ(d) of a disorder kind; NaN where undefined (homogeneous chain; Anderson at q ∈ {0,1}).
double correlation_theory(Disorder disorder, double q, std::size_t distance);

}  // namespace granular
