// granular.breathers (keywords, defaults, docstring and result class in granular/_breathers.py):
// the library's breather branch (orbits/breather_branch.hpp) on a granular.Chain, its arrays and
// the breathers tool's JSON.
#include <cmath>
#include <complex>
#include <nlohmann/json.hpp>
#include <string>

#include "bindings.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/orbits/breather_branch.hpp"
#include "granular/orbits/breather_parameters.hpp"
#include "granular/study/frequency_slips.hpp"

namespace granular::python {
namespace {

py::dict breathers(const PyChain& c, BreatherBranchConfig config) {
  config.chain = c.recipe;
  config.realization = c.realization;
  validate(config);
  warn(frequency_slips(config, front_end_word));  // Hz typed as kHz: near, as the tool
  BreatherBranch branch;
  {
    py::gil_scoped_release release;
    branch = continue_breather(config);
  }
  const py::object meta = metadata("breathers", describe_breather_branch(config, branch));
  py::list points;  // stacked into arrays by granular/_breathers.py
  for (const BreatherPoint& p : branch.points)
    points.append(
        fields("omega freq_khz energy amplitude max_multiplier residual max_open_fraction centre "
               "newton_iterations stable complete verdict_trusted profiles open_fraction multipliers",
               p.omega, p.freq_khz, p.energy, p.amplitude, p.floquet.max_modulus, p.residual, p.max_open_fraction,
               p.centre + 1, p.iterations, p.floquet.stable, p.floquet.complete, p.verdict_trusted, p.x0,
               p.open_fraction, p.floquet.multipliers));
  return fields("points linear_khz seed_mode seed_site seed_khz stop_reason verdict_untrusted_reason metadata", points,
                std::move(branch.linear_khz), branch.seed_mode, branch.seed_site, branch.seed_khz, branch.stop_reason,
                branch.verdict_untrusted_reason, meta);
}

}  // namespace

void bind_breathers(py::module_& m) {
  // granular.breathers's keywords: the rows of breather_parameters(); its chain set from the granular.Chain
  table_class(m, "BreatherBranchConfig", breather_parameters())
      .def_readwrite("seed_profile", &BreatherBranchConfig::seed_profile);
  m.def("_breathers", &breathers);
}

}  // namespace granular::python
