#pragma once
// Inverse participation ratio of a mode in displacement form (docs/physics.md, "The linear spectrum"):
// P⁻¹ = Σ v_n⁴ / (Σ v_n²)², v = M^{-1/2} w for an eigenvector w of the dynamical matrix.
// 1 when one bead moves, about 1/N for a plane wave. Scale-free: w need not be normalized.
#include <cstddef>
#include <vector>

namespace granular {

/// `inverse_sqrt_mass` holds m_n^{-1/2}; any common scale of it cancels.
double displacement_ipr(const double* w, const double* inverse_sqrt_mass, std::size_t n);

/// m_n^{-1/2} for each bead.
std::vector<double> inverse_sqrt_mass(const std::vector<double>& inverse_mass);

}  // namespace granular
