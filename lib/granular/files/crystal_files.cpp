#include "granular/files/crystal_files.hpp"

#include <cmath>

#include "granular/io/csv_writer.hpp"

namespace granular {

void write_crystal_csv(std::ostream& out, const CrystalResult& r) {
  CsvWriter table(out, {"mode", "freq_khz", "omega2", "ipr"});
  const CrystalSpectrum& s = r.spectrum;
  for (std::size_t k = 0; k < s.size(); ++k) table.row(k + 1, s.freq_hz[k] * 1e-3, s.omega2[k], s.ipr[k]);
}

void write_crystal_modes_csv(std::ostream& out, const CrystalResult& r) {
  CsvWriter table(out, {"mode", "bead", "x", "y", "ux", "uy"});
  const CrystalSpectrum& s = r.spectrum;
  const std::size_t n = s.beads, rows = 2 * n;
  for (std::size_t k = 0; k < s.size() && s.vectors.size() >= (k + 1) * rows; ++k)
    for (std::size_t b = 0; b < n; ++b) {
      const double scale = 1 / std::sqrt(r.packing.mass[b]);
      table.row(k + 1, b + 1, r.packing.x[b], r.packing.y[b], scale * s.vectors[k * rows + 2 * b],
                scale * s.vectors[k * rows + 2 * b + 1]);
    }
}

}  // namespace granular
