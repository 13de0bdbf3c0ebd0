#pragma once
// Pearson correlation of a configuration with its cyclic shifts (docs/physics.md, "Correlations of the type sequence").
#include <cstddef>
#include <vector>

#include "granular/model/bead_distribution.hpp"
#include "granular/model/disorder.hpp"

namespace granular {

/// ρ(d) for d = 0 … max_distance, with type 1 → 0 and type 2 → 1. NaN for every d when the
/// configuration has one type only (σ = 0: the coefficient is undefined).
std::vector<double> cyclic_correlation(const Configuration& types, std::size_t max_distance);

/// ρ(d) of real values (per-bead masses of a chain of k types or polydisperse radii): the Pearson
/// coefficient of x_i and x_{(i+d) mod N} with the chain's own mean and variance. Pearson is
/// invariant under x → a x + b, so for two types this is the coefficient of the type indicator
/// above (equal to rounding). NaN for every d when all values are equal.
std::vector<double> cyclic_value_correlation(const std::vector<double>& values, std::size_t max_distance);

/// Infinite-chain ρ(d) of a disorder kind; NaN where undefined (homogeneous chain; Anderson at q ∈ {0,1}).
double correlation_theory(Disorder disorder, double q, std::size_t distance);

/// Infinite-chain ρ(d) of any function of the bead radius (the mass) for a bead distribution:
/// δ_{d0} for independent beads (rule A, polydisperse), 1, 1/2, 0… for dimers of equal beads
/// (RDM1), the two-type formula for RDM2; NaN when every bead is the same (one type of
/// probability 1, or uniform with low = high).
double correlation_theory(const BeadDistribution& beads, std::size_t distance);

}  // namespace granular
