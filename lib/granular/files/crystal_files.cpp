#include "granular/files/crystal_files.hpp"

#include <bit>
#include <cmath>

#include "granular/io/atomic_file.hpp"
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

void write_crystal_ipr_map_csv(std::ostream& out, const CrystalIprMapConfig& config,
                               const std::vector<CrystalIprMapCell>& cells) {
  CsvWriter table(out, {"width", "freq_lo_khz", "freq_hi_khz", "modes", "ipr", "ratio", "ratios"});
  const double bin_khz = config.bin_hz * 1e-3;
  for (const CrystalIprMapCell& cell : cells)
    for (std::size_t b = 0; b < cell.bin_modes.size(); ++b)
      table.row(cell.width, static_cast<double>(b) * bin_khz, static_cast<double>(b + 1) * bin_khz, cell.bin_modes[b],
                cell.bin_ipr[b], cell.bin_ratio[b], cell.bin_ratios[b]);
}

void write_crystal_matrix(const std::string& prefix, const CrystalMatrix& d) {
  static_assert(std::endian::native == std::endian::little && sizeof(std::size_t) == 8);
  const auto write = [&](const std::string& suffix, const auto& values) {
    AtomicFile file(prefix + suffix);
    file.stream().write(reinterpret_cast<const char*>(values.data()),
                        static_cast<std::streamsize>(values.size() * sizeof(values[0])));
    file.commit();
  };
  write(".row_start.u64", d.matrix.row_start);
  write(".column.u64", d.matrix.column);
  write(".value.f64", d.matrix.value);
}

}  // namespace granular
