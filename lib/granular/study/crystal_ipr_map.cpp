#include "granular/study/crystal_ipr_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "granular/blas_library.hpp"
#include "granular/crystal/crystal_matrix.hpp"
#include "granular/crystal/crystal_spectrum.hpp"
#include "granular/crystal/nearest_modes.hpp"
#include "granular/crystal/static_state.hpp"
#include "granular/ensemble/ensemble_runner.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/parameter_json.hpp"

namespace granular {

const ParameterTable<CrystalIprMapConfig>& crystal_ipr_map_parameters() {
  using C = CrystalIprMapConfig;
  static const ParameterTable<C> table = [] {
    ParameterTable<C> t = nested_rows(crystal_parameters(), &C::crystal,
                                      {"lattice", "boundary", "Lx", "Ly", "radius", "precompression", "strain",
                                       "disorder", "seed", "near", "count"});
    t.push_back({"widths", &C::widths, "disorder strengths w in [0, 1), one map row each (comma list)"});
    t.push_back({"realizations", &C::realizations, "crystals per width (>= 1)"});
    t.push_back({"bin_hz", &C::bin_hz, "frequency bin width [Hz] of the IPR and <r> averages"});
    return t;
  }();
  return table;
}

void validate(const CrystalIprMapConfig& c) {
  if (c.widths.empty()) throw InvalidInput("widths", ": no values");
  for (double w : c.widths)
    if (!(w >= 0 && w < 1)) throw InvalidInput("widths", " " + format_number(w) + ": must be in [0, 1)");
  if (c.realizations < 1) throw InvalidInput("realizations", " 0: must be >= 1");
  if (!(c.bin_hz > 0) || !std::isfinite(c.bin_hz))
    throw InvalidInput("bin_hz", " " + format_number(c.bin_hz) + ": must be finite and > 0");
  make_packing(c.crystal.packing);  // its own checks
  // near and count, as the crystal checks them (the rest of its case is the map's widths' business)
  CrystalCase modes;
  modes.packing = c.crystal.packing, modes.near = c.crystal.near, modes.count = c.crystal.count;
  if (!modes.near && modes.count != CrystalCase{}.count)
    throw InvalidInput("count", " " + std::to_string(modes.count) + ": takes effect only with `near`");
  validate(modes);
}

std::vector<CrystalIprMapCell> crystal_ipr_map(const CrystalIprMapConfig& c, const RunOptions& run) {
  validate(c);
  validate(run);
  if (run.skip_failed) throw InvalidInput("skip_failed", ": the crystal IPR map leaves no crystal out");

  // Task t is realization t % each of width t / each; its row: the ascending frequencies [Hz],
  // then their IPRs (what the bins need, and what a checkpoint keeps).
  const std::size_t each = c.realizations;
  EnsembleOptions ensemble;
  ensemble.realizations = c.widths.size() * each;
  ensemble.threads = run.threads;
  ensemble.checkpoint = run.checkpoint;
  ensemble.resume = run.resuming();
  ensemble.fresh = run.fresh;
  ensemble.accept_other_version = run.accept_other_version;
  ensemble.parameters = describe_rows(c, crystal_ipr_map_parameters()).dump();
  ensemble.progress = run.progress;
  ensemble.cancelled = run.cancelled;
  const SerialBlas serial;  // the crystals are the parallelism, and each the same bits on any rank
  const std::vector<std::vector<double>> rows = run_ensemble(ensemble, [&](std::uint64_t task, int) {
    const double width = c.widths[task / each];
    const Packing p = make_packing(
        disordered(c.crystal.packing, {c.crystal.disorder.kind, width, c.crystal.disorder.seed, task % each}));
    const CrystalMatrix d = crystal_matrix(p, static_state(p));
    // ARPACK, one process per crystal: the crystals, not the ranks, share the work.
    const CrystalSpectrum s =
        c.crystal.near ? crystal_nearest_modes(d, *c.crystal.near * 1e3, c.crystal.count) : crystal_spectrum(d);
    std::vector<double> row = s.freq_hz;
    row.insert(row.end(), s.ipr.begin(), s.ipr.end());
    return row;
  });
  if (!MpiContext::instance().root()) return {};
  std::vector<CrystalSpectrum> spectra(rows.size());
  for (std::size_t t = 0; t < rows.size(); ++t) {
    const std::size_t modes = rows[t].size() / 2;
    spectra[t].freq_hz.assign(rows[t].begin(), rows[t].begin() + static_cast<std::ptrdiff_t>(modes));
    spectra[t].ipr.assign(rows[t].begin() + static_cast<std::ptrdiff_t>(modes), rows[t].end());
    spectra[t].omega2.resize(modes);  // size() counts them; the bins read f and the IPR only
  }

  std::vector<CrystalIprMapCell> cells;
  for (std::size_t w = 0; w < c.widths.size(); ++w) {
    const double width = c.widths[w];
    const std::span<const CrystalSpectrum> cell_spectra(spectra.data() + w * each, each);
    double top = 0;
    for (const CrystalSpectrum& s : cell_spectra) top = std::max(top, s.freq_hz.back());
    const auto bins = static_cast<std::size_t>(std::floor(top / c.bin_hz)) + 1;
    CrystalIprMapCell cell;
    cell.width = width;
    cell.bin_modes.assign(bins, 0);
    cell.bin_ratios.assign(bins, 0);
    std::vector<double> ipr_sum(bins, 0.0), ratio_sum(bins, 0.0);
    auto bin_of = [&](double f) { return std::min(bins - 1, static_cast<std::size_t>(std::max(0.0, f) / c.bin_hz)); };
    for (const CrystalSpectrum& s : cell_spectra) {
      for (std::size_t k = 0; k < s.size(); ++k)
        ++cell.bin_modes[bin_of(s.freq_hz[k])], ipr_sum[bin_of(s.freq_hz[k])] += s.ipr[k];
      // ⟨r⟩ of each bin's run of levels: the levels are ascending, so a bin's are contiguous.
      for (std::size_t first = 0; first < s.size();) {
        const std::size_t b = bin_of(s.freq_hz[first]);
        std::size_t last = first;
        while (last < s.size() && bin_of(s.freq_hz[last]) == b) ++last;
        const SpacingRatio r = spacing_ratio(std::span<const double>(s.freq_hz.data() + first, last - first));
        if (r.count > 0) ratio_sum[b] += r.mean * static_cast<double>(r.count), cell.bin_ratios[b] += r.count;
        first = last;
      }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t b = 0; b < bins; ++b) {
      cell.bin_ipr.push_back(cell.bin_modes[b] > 0 ? ipr_sum[b] / static_cast<double>(cell.bin_modes[b]) : nan);
      cell.bin_ratio.push_back(cell.bin_ratios[b] > 0 ? ratio_sum[b] / static_cast<double>(cell.bin_ratios[b]) : nan);
    }
    cells.push_back(std::move(cell));
  }
  return cells;
}

}  // namespace granular
