#pragma once
// Hertz contact coefficient A of a bond: force = A δ^{3/2} for overlap δ (SPEC §1).
#include <limits>

#include "granular/model/material.hpp"

namespace granular {

/// Radius of a flat wall: the Hertz formula's limit R → ∞.
inline constexpr double flat_wall = std::numeric_limits<double>::infinity();

/// A = 4 E_a E_b sqrt(R_a R_b / (R_a + R_b)) / (3 [E_b (1-ν_a²) + E_a (1-ν_b²)]).
/// Either radius may be `flat_wall` (sphere–wall contact: the effective radius is the sphere's).
double hertz_coefficient(const Material& a, double radius_a, const Material& b, double radius_b);

}  // namespace granular
