#pragma once
// The four ways of drawing a bidisperse chain (docs/physics.md, "Disorder"). A configuration is a sequence of
// bead types, 1 (radius R1) or 2 (radius ξ R1).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "granular/model/random_stream.hpp"

namespace granular {

enum class Disorder {
  homogeneous,  ///< "h": all type 1
  anderson,     ///< "A": each bead type 1 with probability q
  rdm1,         ///< "RDM1": each dimer "1 1" with probability q, else "2 2"
  rdm2,         ///< "RDM2": each dimer "1 2" with probability q, else "2 1"
};

using Configuration = std::vector<std::uint8_t>;  ///< bead types, each 1 or 2

/// Parses h, A, RDM1, RDM2 (case-insensitive); throws InvalidInput naming the choices.
Disorder parse_disorder(std::string_view name);
std::string to_string(Disorder disorder);

/// Draws N bead types. For odd N the dimer models draw ⌈N/2⌉ dimers and drop the last bead.
/// Bead i uses the i-th uniform of the stream (dimer j the j-th), so one stream drawn at
/// several q gives nested configurations.
Configuration sample_configuration(Disorder disorder, double q, std::size_t n, RandomStream& stream);

/// Configuration of realization r of seed s: a pure function of (s, r, disorder, q, N).
Configuration realization_configuration(Disorder disorder, double q, std::size_t n, std::uint64_t seed,
                                        std::uint64_t realization);

/// Radii of a configuration: type 1 → r1, type 2 → ξ r1.
std::vector<double> radii_of(const Configuration& types, double r1, double xi);

/// Throws InvalidInput unless 0 ≤ q ≤ 1 and 0 < ξ ≤ 1.
void validate_probability(double q);
void validate_size_ratio(double xi);

}  // namespace granular
