#pragma once
// The linearized chain (docs/physics.md, "The linear spectrum"): the symmetric dynamical matrix D = M^{-1/2} K M^{-1/2}
// [1/s²], K the tridiagonal stiffness matrix of the bonds' linear stiffnesses B_k (model/contact_law.hpp). Its
// eigenvalues are ω² ≥ 0; an eigenvector w of D gives the displacement mode v = M^{-1/2} w, which is why the matrix
// carries M^{-1/2}: every IPR is computed from v, not w.
#include <vector>

#include "granular/linear/sym_tridiagonal.hpp"
#include "granular/model/bead_source.hpp"
#include "granular/model/chain.hpp"

namespace granular {

struct DynamicalMatrix : SymTridiagonal {
  std::vector<double> inverse_sqrt_mass;  ///< m_n^{-1/2} [kg^{-1/2}], N entries
};

/// D(i,i) = (B_i + B_{i+1} + k_i)/m_i (k_i the on-site spring, if any), D(i,i+1) = -B_{i+1}/sqrt(m_i m_{i+1}) [1/s²].
/// Throws InvalidInput when F0 = 0 without on-site springs (the sonic vacuum has no linear limit); at F0 = 0 with
/// them, D is diagonal: each bead's own k_i/m_i.
DynamicalMatrix dynamical_matrix(const Chain& chain);

/// The same matrix, bit for bit, read a piece at a time from a bead source (model/bead_source.hpp):
/// a drawn chain's matrix is built without storing the chain (2 N doubles and the N of
/// inverse_sqrt_mass, not the chain's arrays beside them).
DynamicalMatrix dynamical_matrix(const BeadSource& beads);

/// Frequency in kHz of an eigenvalue ω² [1/s²] (negative round-off clamps to 0).
double frequency_khz(double omega_squared);

/// ω² [1/s²] of a frequency in kHz.
double omega_squared_of_khz(double khz);

}  // namespace granular
