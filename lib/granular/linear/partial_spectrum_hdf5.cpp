// HDF5 output of a partial spectrum (kept apart so the solvers do not depend on file formats).
#include <cstdint>

#include <Eigen/Core>

#include "granular/io/hdf5_file.hpp"
#include "granular/linear/partial_spectrum.hpp"

namespace granular {

void write_partial_spectrum_hdf5(const std::string& path, const PartialSpectrum& s,
                                 const std::vector<double>& inverse_sqrt_mass) {
  Hdf5File file(path);
  file.write("mode", std::vector<std::uint64_t>(s.mode.begin(), s.mode.end()));
  file.write("omega2", s.omega2);
  file.write("freq_khz", s.freq_khz);
  file.write("ipr", s.ipr);
  file.write("residual", s.residual);
  file.write("inverse_sqrt_mass", inverse_sqrt_mass);
  if (s.vectors.cols() > 0) {
    // Eigen is column-major N × K: its memory is exactly the row-major K × N array.
    file.write("eigenvectors", s.vectors.data(), static_cast<std::size_t>(s.vectors.cols()),
               static_cast<std::size_t>(s.vectors.rows()));
  }
  file.attribute("method", s.method);
  file.attribute("eigenvectors_layout",
                 "row j = unit eigenvector w of the dynamical matrix for mode[j]; displacement v = w * inverse_sqrt_mass");
  file.commit();
}

}  // namespace granular
