#pragma once
// Random chains beyond the paper's two bead types: k types with given probabilities,
// or polydisperse radii drawn from a distribution — realization r of seed s again a pure function
// of (s, r, distribution, N), whatever the thread, rank or order. Bead i (dimer j under the
// dimer rules) uses the i-th (j-th) uniform of the Philox stream keyed by (s, r), exactly as
// sample_configuration does, so two types with probabilities (q, 1 − q) and radii (R1, ξ R1)
// give bit for bit the chains of realization_configuration + radii_of.
//
//   BeadDistribution three{.radii = {4.76e-3, 3e-3, 2e-3}, .probabilities = {0.5, 0.3, 0.2}};
//   auto chain = from_radii(realization_radii(three, 1000, /*seed*/ 1, /*realization*/ 0));
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "granular/model/disorder.hpp"

namespace granular {

struct BeadDistribution {
  enum class Kind {
    types,    ///< k types: radii[t] with probabilities[t]
    uniform,  ///< radius uniform on [low, high]
    normal,   ///< radius normal (mean, sd) truncated below at `minimum`
  } kind = Kind::types;
  std::vector<double> radii{};          ///< types: the k radii [m]
  std::vector<double> probabilities{};  ///< types: k probabilities ≥ 0 summing to 1 (to 1e-9)
  /// types: anderson — each bead independently; rdm1 — each dimer "t t"; rdm2 — two types only,
  /// dimer "1 2" with probabilities[0], else "2 1". (Polydisperse radii are drawn per bead.)
  Disorder rule = Disorder::anderson;
  double low = 0, high = 0;              ///< uniform [m], 0 < low ≤ high
  double mean = 0, sd = 0, minimum = 0;  ///< normal [m], sd > 0, 0 < minimum < mean + 8 sd
};

/// Throws InvalidInput naming the field (radii, probabilities, rule, low, high, mean, sd, minimum).
void validate(const BeadDistribution& d);

/// The N radii [m] of realization `realization` of seed `seed`.
std::vector<double> realization_radii(const BeadDistribution& d, std::size_t n, std::uint64_t seed,
                                      std::uint64_t realization);

/// Radius of one bead from its uniform u ∈ [0, 1) (polydisperse kinds): inverse CDF, so the
/// draw is one uniform per bead whatever the distribution.
double radius_from_uniform(const BeadDistribution& d, double u);

/// Every parameter, for metadata and checkpoint identities.
std::string describe(const BeadDistribution& d);
/// The inverse of describe (numbers in shortest round-trip form read back exactly). Throws
/// InvalidInput naming "beads".
BeadDistribution parse_bead_distribution(const std::string& text);

/// The plausible radius range of the Hertz contact law for these tools [m]: outside it a radius
/// is likely a unit slip (4.76 typed for 4.76e-3) and deserves a warning, not an error.
inline constexpr double plausible_radius_min = 1e-4, plausible_radius_max = 0.1;
inline bool plausible_radius(double r) { return r >= plausible_radius_min && r <= plausible_radius_max; }

}  // namespace granular
