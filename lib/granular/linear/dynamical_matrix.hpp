#pragma once
// The linearized chain (SPEC §3): bond stiffness B_k = (3/2) A_k^{2/3} F0^{1/3} and the
// symmetric dynamical matrix D = M^{-1/2} K M^{-1/2}, whose eigenvalues are ω² ≥ 0.
// An eigenvector w of D gives the displacement mode v = M^{-1/2} w.
#include <vector>

#include "granular/linear/sym_tridiagonal.hpp"
#include "granular/model/chain.hpp"

namespace granular {

/// Linear stiffness of a Hertz bond with coefficient A under precompression F0 [N/m].
double linear_stiffness(double contact, double precompression);

/// B_k for every bond of the chain (N+1 values).
std::vector<double> linear_stiffness(const Chain& chain);

/// D(i,i) = (B_i + B_{i+1})/m_i, D(i,i+1) = -B_{i+1}/sqrt(m_i m_{i+1}) [1/s²].
/// Throws InvalidInput when F0 = 0 (the sonic vacuum has no linear limit).
SymTridiagonal dynamical_matrix(const Chain& chain);

/// Frequency in kHz of an eigenvalue ω² (negative round-off clamps to 0).
double frequency_khz(double omega_squared);

}  // namespace granular
