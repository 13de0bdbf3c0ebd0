#include "granular/study/spectrum_file.hpp"

#include <cstdint>

#include "granular/io/hdf5_file.hpp"

namespace granular {

void write_spectrum_hdf5(const std::string& path, const Spectrum& s, const DynamicalMatrix& matrix) {
  Hdf5File file(path);
  file.write("mode", std::vector<std::uint64_t>(s.mode.begin(), s.mode.end()));
  file.write("omega2", s.omega2);
  file.write("freq_khz", s.freq_khz);
  file.write("ipr", s.ipr);
  file.write("residual", s.residual);
  file.write("inverse_sqrt_mass", matrix.inverse_sqrt_mass);
  // Column-major N × K is exactly the row-major K × N array.
  if (!s.vectors.empty()) file.write("eigenvectors", s.vectors.data(), s.size(), s.beads);
  file.attribute("method", s.info.method);
  file.attribute(
      "eigenvectors_layout",
      "row j = unit eigenvector w of the dynamical matrix for mode[j]; displacement v = w * inverse_sqrt_mass");
  file.commit();
}

}  // namespace granular
