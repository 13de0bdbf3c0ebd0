#pragma once
// Weakly nonlinear descriptions of a precompressed Hertz bond (SPEC §3).

namespace granular {

/// Taylor coefficients of the Hertz force in the strain x about the precompressed state:
/// F(x) ≈ b1 x + b2 x² + b3 x³ (the FPU chain).
struct FpuCoefficients {
  double b1;  ///< (3/2) A^{2/3} F0^{1/3} [N/m]
  double b2;  ///< (3/8) A^{4/3} F0^{-1/3} [N/m²]
  double b3;  ///< -(3/48) A² F0^{-1} [N/m³]
  /// 3 b1 b3 − 4 b2²: band-edge waves are modulationally unstable only if it is > 0
  /// (the paper prints b2 without its square); always negative for Hertz.
  double modulational_discriminant() const { return 3 * b1 * b3 - 4 * b2 * b2; }
};

/// Throws InvalidInput unless A > 0 and F0 > 0.
FpuCoefficients fpu_coefficients(double contact, double precompression);

/// Static overlap Δ = (F0/A)^{2/3} [m].
double static_overlap(double contact, double precompression);

/// ε = α/Δ: the strain of a displacement kick α at one bead of a homogeneous chain relative
/// to the static overlap; +∞ at F0 = 0 (no linear limit at all).
double nonlinearity_ratio(double alpha, double contact, double precompression);

}  // namespace granular
