// granular.crystal (keywords, defaults, docstring and result class in granular/_crystal.py): the
// library's CrystalCase bound by its table (crystal_parameters()), one call that runs the job
// (GIL released) and returns its arrays with the library's own JSON.
#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "granular/crystal/crystal_study.hpp"

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

}  // namespace

void bind_crystal(py::module_& m) {
  table_class(m, "CrystalCase", crystal_parameters());
  m.def("_crystal", &crystal);
}

}  // namespace granular::python
