#include "granular/orbits/breather_crossing.hpp"

#include <algorithm>
#include <cmath>

#include "granular/number_format.hpp"
#include "granular/orbits/breather_branch.hpp"

namespace granular {

double mode_overlap(const Spectrum& modes, const DynamicalMatrix& d, std::size_t j, std::span<const double> x) {
  const std::span<const double> v = modes.vector(j);
  double peak = 0, norm = 0, shared = 0;
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double mass = 1 / (d.inverse_sqrt_mass[n] * d.inverse_sqrt_mass[n]);
    peak = std::max(peak, std::abs(v[n] * d.inverse_sqrt_mass[n]));
    norm += mass * x[n] * x[n];
    shared += mass * x[n] * x[n] * std::abs(v[n] * d.inverse_sqrt_mass[n]);
  }
  return peak > 0 && norm > 0 ? shared / norm / peak : 0;
}

std::optional<ModeCrossing> blocking_crossing(const Spectrum& modes, const DynamicalMatrix& d,
                                              std::span<const double> x, double from_khz, double to_khz) {
  const std::vector<double>& f = modes.freq_khz;
  const bool up = to_khz > from_khz;
  const bool from_outside = !inside_linear_band(f, from_khz);
  bool first = true;
  for (std::size_t k = 0; k < f.size(); ++k) {
    const std::size_t j = up ? k : f.size() - 1 - k;  // nearest from_khz first
    if ((f[j] - to_khz) * (f[j] - from_khz) >= 0) continue;
    const double overlap = mode_overlap(modes, d, j, x);
    if (overlap >= crossing_overlap)
      return ModeCrossing{.mode = j + 1, .freq_khz = f[j], .overlap = overlap, .band_edge = first && from_outside};
    first = false;
  }
  return std::nullopt;
}

std::string describe(const ModeCrossing& c) {
  return "reached linear mode " + std::to_string(c.mode) + " at " + format_number(c.freq_khz) + " kHz, overlap " +
         format_number(std::round(c.overlap * 1e4) / 1e4) +
         " with the breather (>= " + format_number(crossing_overlap) + (c.band_edge ? "; band edge)" : ")");
}

}  // namespace granular
