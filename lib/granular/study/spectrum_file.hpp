#pragma once
// A spectrum with its eigenvectors as an HDF5 file (where the linear module meets the file
// formats: neither knows the other).
#include <string>

#include "granular/linear/spectrum.hpp"

namespace granular {

/// Writes `spectrum` and the matrix's m^{-1/2} to an HDF5 file that appears whole or not at all.
/// Datasets: /mode, /omega2 [1/s²], /freq_khz, /ipr, /residual (K each), /inverse_sqrt_mass (N),
/// /eigenvectors (K × N, row j = unit w of mode j; displacements v = w ⊙ inverse_sqrt_mass) when
/// the spectrum holds vectors; attribute "method". Throws IoError.
void write_spectrum_hdf5(const std::string& path, const Spectrum& spectrum, const DynamicalMatrix& matrix);

}  // namespace granular
