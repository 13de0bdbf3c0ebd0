#include "granular/crystal/crystal_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>

#include "granular/detail/memory_limit.hpp"
#include "granular/error.hpp"
#include "granular/linear/detail/lapack.hpp"
#include "granular/number_format.hpp"

namespace granular {

CrystalSpectrum crystal_spectrum(const CrystalMatrix& d, const CrystalSpectrumConfig& config) {
  // Refused before anything is allocated: dsyevd's workspace, 1 + 6n + 2n² doubles for n = 2N, must
  // fit LAPACK's 32-bit sizes (N <= 16383), and it and the matrix (3n² doubles) this process's memory.
  const auto n64 = static_cast<std::int64_t>(d.rows());
  const std::string instead = "; crystal_nearest_modes solves a few modes of a sparse crystal of any size";
  if (1 + 6 * n64 + 2 * n64 * n64 > std::numeric_limits<int>::max())
    throw InvalidInput("N", " " + std::to_string(d.beads()) +
                                ": every mode needs dsyevd's workspace of 2(2N)^2 + 6(2N) + 1 doubles, past LAPACK's "
                                "32-bit sizes (N <= 16383)" +
                                instead);
  const double bytes =
      8.0 * (3.0 * static_cast<double>(n64) * static_cast<double>(n64) + 6.0 * static_cast<double>(n64));
  if (const detail::MemoryLimit memory = detail::memory_limit(); memory.bytes > 0 && bytes > memory.bytes)
    throw InvalidInput("N", " " + std::to_string(d.beads()) + ": every mode needs " +
                                format_number(std::round(bytes / 1e8) / 10) + " GB, more than the " +
                                format_number(std::round(memory.bytes / 1e8) / 10) + " GB this process may use (" +
                                memory.source + ")" + instead);
  const int n = static_cast<int>(n64);
  std::vector<double> a = dense(d);  // row-major and symmetric: LAPACK's column-major reads the same
  CrystalSpectrum out;
  out.beads = d.beads();
  out.omega2.assign(d.rows(), 0.0);
  // Vectors always: the IPRs need them.
  const char jobz = 'V', uplo = 'L';
  int info = 0, lwork = -1, liwork = -1, iwork_query = 0;
  double work_query = 0;
  dsyevd_(&jobz, &uplo, &n, a.data(), &n, out.omega2.data(), &work_query, &lwork, &iwork_query, &liwork, &info, 1, 1);
  if (info != 0) throw NumericalError("dsyevd workspace query failed: info " + std::to_string(info));
  lwork = detail::lapack_int(static_cast<std::int64_t>(work_query), "dsyevd's workspace");
  liwork = iwork_query;
  std::vector<double> work(static_cast<std::size_t>(lwork));
  std::vector<int> iwork(static_cast<std::size_t>(liwork));
  if (n > 0)
    dsyevd_(&jobz, &uplo, &n, a.data(), &n, out.omega2.data(), work.data(), &lwork, iwork.data(), &liwork, &info, 1, 1);
  if (info != 0) throw NumericalError("dsyevd failed: info " + std::to_string(info));
  out.freq_hz.resize(d.rows());
  for (std::size_t k = 0; k < d.rows(); ++k)
    out.freq_hz[k] = std::copysign(std::sqrt(std::fabs(out.omega2[k])), out.omega2[k]) / (2 * std::numbers::pi);
  out.ipr.resize(d.rows());
  for (std::size_t k = 0; k < d.rows(); ++k)
    out.ipr[k] = vector_ipr({a.data() + k * d.rows(), d.rows()}, d.inverse_sqrt_mass);
  if (config.vectors) out.vectors = std::move(a);
  return out;
}

double vector_ipr(std::span<const double> w, std::span<const double> inverse_sqrt_mass) {
  double sum2 = 0, sum4 = 0;
  for (std::size_t b = 0; b < inverse_sqrt_mass.size(); ++b) {
    const double s = inverse_sqrt_mass[b] * inverse_sqrt_mass[b];
    const double amplitude2 = s * (w[2 * b] * w[2 * b] + w[2 * b + 1] * w[2 * b + 1]);
    sum2 += amplitude2, sum4 += amplitude2 * amplitude2;
  }
  return sum4 / (sum2 * sum2);
}

SpacingRatio spacing_ratio(std::span<const double> levels) {
  SpacingRatio r;
  double sum = 0;
  for (std::size_t n = 0; n + 2 < levels.size(); ++n) {
    const double s0 = levels[n + 1] - levels[n], s1 = levels[n + 2] - levels[n + 1];
    const double hi = std::max(s0, s1);
    if (!(hi > 0)) continue;
    sum += std::min(s0, s1) / hi;
    ++r.count;
  }
  r.mean = r.count > 0 ? sum / static_cast<double>(r.count) : std::nan("");
  return r;
}

namespace {
void check_window(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    throw InvalidInput("window", " " + format_number(lo) + ":" + format_number(hi) + ": must be finite with lo < hi");
}
}  // namespace

SpacingRatio spacing_ratio(const CrystalSpectrum& spectrum, double lo_hz, double hi_hz) {
  check_window(lo_hz, hi_hz);
  const auto first = std::lower_bound(spectrum.freq_hz.begin(), spectrum.freq_hz.end(), lo_hz);
  const auto last = std::upper_bound(first, spectrum.freq_hz.end(), hi_hz);
  const auto offset = static_cast<std::size_t>(first - spectrum.freq_hz.begin());
  return spacing_ratio(std::span<const double>(spectrum.freq_hz.data() + offset, static_cast<std::size_t>(last - first)));
}

FrequencyHistogram frequency_histogram(const CrystalSpectrum& spectrum, std::size_t bins, double lo_hz, double hi_hz) {
  if (bins < 1) throw InvalidInput("bins", " 0: must be >= 1");
  check_window(lo_hz, hi_hz);
  FrequencyHistogram h;
  const double width = (hi_hz - lo_hz) / static_cast<double>(bins);
  h.edges.resize(bins + 1);
  for (std::size_t k = 0; k <= bins; ++k) h.edges[k] = lo_hz + width * static_cast<double>(k);
  h.edges[bins] = hi_hz;
  h.counts.assign(bins, 0);
  for (double f : spectrum.freq_hz) {
    if (f < lo_hz || f > hi_hz) continue;
    const auto k = std::min(bins - 1, static_cast<std::size_t>((f - lo_hz) / width));
    ++h.counts[k];
  }
  h.density.resize(bins);
  const double modes = static_cast<double>(spectrum.size());
  for (std::size_t k = 0; k < bins; ++k) h.density[k] = static_cast<double>(h.counts[k]) / (modes * width);
  return h;
}

}  // namespace granular
