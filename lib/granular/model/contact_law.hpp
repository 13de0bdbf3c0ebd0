#pragma once
// The Hertz contact law of two elastic bodies and everything derived from it (docs/physics.md, "The chain", §3): the
// contact coefficient A (force = A δ^{3/2} at overlap δ), the static overlap Δ under a
// precompression F0, the linear stiffness B, the FPU (cubic) expansion and the nonlinearity
// ratio ε. This is the one home of these formulas: chains, dynamical matrices, band edges and
// force laws all call them.
#include <limits>

#include "granular/model/material.hpp"

namespace granular {

/// Radius of a flat wall: the Hertz formula's limit R → ∞.
inline constexpr double flat_wall = std::numeric_limits<double>::infinity();

/// A = 4 E_a E_b sqrt(R_a R_b / (R_a + R_b)) / (3 [E_b (1-ν_a²) + E_a (1-ν_b²)]) [N/m^{3/2}].
/// Either radius may be `flat_wall` (sphere–wall contact: the effective radius is the sphere's).
double hertz_coefficient(const Material& a, double radius_a, const Material& b, double radius_b);

/// Static overlap Δ = (F0/A)^{2/3} [m] of a bond with coefficient A under precompression F0 [N].
double static_overlap(double contact, double precompression);

/// Hertz force F = A [δ]_+^{3/2} [N] at overlap δ [m] (0 for an open contact, δ ≤ 0).
double hertz_force(double contact, double overlap);

/// Hertz normal stiffness k_n = dF/dδ = (3/2) A [δ]_+^{1/2} [N/m] at overlap δ [m].
double hertz_stiffness(double contact, double overlap);

/// Hertz energy (2/5) A [δ]_+^{5/2} [J] at overlap δ [m]: its δ-derivative is hertz_force.
double hertz_energy(double contact, double overlap);

/// Linear stiffness B = dF/dδ at Δ = (3/2) A^{2/3} F0^{1/3} [N/m]; 0 at F0 = 0.
double linear_stiffness(double contact, double precompression);

/// Taylor coefficients of the Hertz force in the strain x about the precompressed state:
/// F(x) ≈ b1 x + b2 x² + b3 x³ (the FPU chain).
struct FpuCoefficients {
  double b1;  ///< (3/2) A^{2/3} F0^{1/3} = linear_stiffness [N/m]
  double b2;  ///< (3/8) A^{4/3} F0^{-1/3} [N/m²]
  double b3;  ///< -(3/48) A² F0^{-1} [N/m³]
  /// 3 b1 b3 − 4 b2²: band-edge waves are modulationally unstable only if it is > 0
  /// (the paper prints b2 without its square); always negative for Hertz.
  double modulational_discriminant() const { return 3 * b1 * b3 - 4 * b2 * b2; }
};

/// Throws InvalidInput unless A > 0 and F0 > 0 (both finite).
FpuCoefficients fpu_coefficients(double contact, double precompression);

/// ε = |α|/Δ: the strain of a displacement kick α [m] at one bead of a homogeneous chain relative
/// to the static overlap; +∞ at F0 = 0 (no linear limit at all).
double nonlinearity_ratio(double alpha, double contact, double precompression);

}  // namespace granular
