#pragma once
// Elastic material of a bead or a wall, SI units.

#include <numbers>

#include <nlohmann/json_fwd.hpp>

namespace granular {

struct Material {
  double young = 193e9;      ///< Young modulus E [Pa]
  double poisson = 0.3;      ///< Poisson ratio ν [-]
  double density = 8027.17;  ///< mass density ρ [kg/m³]
};

/// The paper's stainless steel (docs/physics.md, "The chain").
inline constexpr Material steel{193e9, 0.3, 8027.17};

/// Mass of a sphere of radius r [m]: ρ (4/3) π r³ [kg] (the one home of this formula).
inline double sphere_mass(const Material& material, double r) {
  return material.density * (4.0 / 3.0) * std::numbers::pi * r * r * r;
}
/// Radius [m] of a sphere of mass m [kg]: the inverse of sphere_mass.
double sphere_radius(const Material& material, double m);

/// Throws InvalidInput unless E > 0, -1 < ν < 0.5 and ρ > 0 (all finite). `what` names the owner.
void validate(const Material& material, const char* what);

/// The material as descriptions give it: E_Pa, nu, rho_kg_m3.
nlohmann::json describe(const Material& material);

}  // namespace granular
