#pragma once
// Elastic material of a bead or a wall, SI units.

namespace granular {

struct Material {
  double young = 193e9;      ///< Young modulus E [Pa]
  double poisson = 0.3;      ///< Poisson ratio ν [-]
  double density = 8027.17;  ///< mass density ρ [kg/m³]
};

/// The paper's stainless steel (SPEC §1).
inline constexpr Material steel{193e9, 0.3, 8027.17};

/// Throws InvalidInput unless E > 0, -1 < ν < 0.5 and ρ > 0 (all finite). `what` names the owner.
void validate(const Material& material, const char* what);

}  // namespace granular
