// granular.crystal (keywords, defaults, docstring and result class in granular/_crystal.py): the
// library's CrystalCase bound by its table (crystal_parameters()), one call that runs the job
// (GIL released) and returns its arrays with the library's own JSON.
#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "granular/crystal/crystal_study.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/parameter_json.hpp"
#include "granular/study/crystal_ipr_map.hpp"

namespace granular::python {
namespace {

py::dict crystal(const CrystalCase& c) {
  CrystalResult r;
  {
    py::gil_scoped_release free;
    r = crystal_study(c);
  }
  const py::object meta = metadata("crystal", describe(c, r));
  CrystalSpectrum& s = r.spectrum;
  std::vector<double> freq_khz(s.freq_hz.size());
  for (std::size_t k = 0; k < freq_khz.size(); ++k) freq_khz[k] = s.freq_hz[k] * 1e-3;
  return fields("freq_khz omega2 ipr vectors x y mass radius spacing_ratio ratios_averaged method imbalance metadata",
                std::move(freq_khz), std::move(s.omega2), std::move(s.ipr), std::move(s.vectors),
                std::move(r.packing.x), std::move(r.packing.y), std::move(r.packing.mass), std::move(r.packing.radius),
                r.ratio.mean, r.ratio.count, r.method, r.state.imbalance, meta);
}

/// The map's cells (one per width, its bins) and the JSON of the config (describe_rows).
py::dict ipr_map_of_crystals(const CrystalIprMapConfig& c, const PyRun& options) {
  const int threads = options.thread_request();
  std::vector<CrystalIprMapCell> cells;
  run_long("crystal_ipr_map", c.widths.size() * c.realizations, options,
           [&](const RunOptions& run) { cells = granular::crystal_ipr_map(c, run); });
  if (!options.checkpoint.empty()) CheckpointLog::remove_all(options.checkpoint);  // complete: the map is in memory
  nlohmann::json described;
  described["parameters"] = describe_rows(c, crystal_ipr_map_parameters());
  described["threads"] = resolve_threads(threads);
  py::list out;
  for (CrystalIprMapCell& cell : cells)
    out.append(fields("width bin_modes bin_ipr bin_ratio bin_ratios", cell.width, std::move(cell.bin_modes),
                      std::move(cell.bin_ipr), std::move(cell.bin_ratio), std::move(cell.bin_ratios)));
  return fields("cells bin_hz metadata", out, c.bin_hz, metadata("crystal_ipr_map", described));
}

}  // namespace

void bind_crystal(py::module_& m) {
  table_class(m, "CrystalCase", crystal_parameters());
  m.def("_crystal", &crystal);
  table_class(m, "CrystalIprMapConfig", crystal_ipr_map_parameters());
  m.def("_crystal_ipr_map", &ipr_map_of_crystals);
}

}  // namespace granular::python
