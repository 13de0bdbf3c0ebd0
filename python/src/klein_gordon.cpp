// granular.klein_gordon (keywords, defaults, docstring and result class in granular/_klein_gordon.py):
// the library's KleinGordonCase bound by its table (klein_gordon_parameters()), one call that runs
// the job (GIL released) and returns its arrays with the library's own JSON.
#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "granular/klein_gordon/klein_gordon_study.hpp"

namespace granular::python {
namespace {

py::dict klein_gordon(const KleinGordonCase& c) {
  KleinGordonResult r;
  {
    py::gil_scoped_release free;
    r = klein_gordon_study(c);
  }
  const py::object meta = metadata("klein_gordon", describe(c, r));
  KleinGordonEnsemble& e = r.ensemble;
  // Each realization's curves, realization-major (reshaped to (realizations, samples) in Python).
  std::vector<double> m2, participation, mle;
  for (const KleinGordonRun& run : e.runs) {
    m2.insert(m2.end(), run.m2.begin(), run.m2.end());
    participation.insert(participation.end(), run.participation.begin(), run.participation.end());
    mle.insert(mle.end(), run.mle.begin(), run.mle.end());
  }
  // Realization 0's site energies, sample-major (reshaped to (samples, N) in Python); empty without.
  std::vector<double> energy_map = std::move(e.runs.front().energy_map);
  return fields("t m2 P mle mean_log10_mle runs_m2 runs_P runs_mle energy_map max_energy_error metadata",
                std::move(e.time), std::move(e.m2), std::move(e.participation), std::move(e.mle),
                std::move(e.mean_log10_mle), std::move(m2), std::move(participation), std::move(mle),
                std::move(energy_map), r.max_energy_error, meta);
}

}  // namespace

void bind_klein_gordon(py::module_& m) {
  table_class(m, "KleinGordonCase", klein_gordon_parameters());
  m.def("_klein_gordon", &klein_gordon);
}

}  // namespace granular::python
