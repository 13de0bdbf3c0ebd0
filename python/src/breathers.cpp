// granular.breathers (keywords, defaults, docstring and result class in granular/_breathers.py):
// the library's breather branch (study/breather_branch.hpp) on a granular.Chain, its arrays and
// the breathers tool's JSON.
#include <cmath>
#include <complex>
#include <nlohmann/json.hpp>
#include <string>

#include "bindings.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/study/breather_branch.hpp"
#include "granular/study/frequency_slips.hpp"

namespace granular::python {
namespace {

py::dict breathers(const PyChain& c, BreatherBranchConfig config) {
  config.chain = c.recipe;
  config.realization = c.realization;
  validate(config);
  warn(frequency_slips(config, [](const std::string& p) { return p; }));  // Hz typed as kHz: near_khz, as the tool
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
  using B = BreatherBranchConfig;  // granular.breathers's keywords, its chain set from the granular.Chain
  config_class(m, "BreatherBranchConfig",
               "mode near_khz start_khz target_khz step_khz max_points stop_at_opening stability_tolerance shooting "
               "seed_profile site start_offset",
               &B::mode, &B::near_khz, &B::start_khz, &B::target_khz, &B::step_khz, &B::max_points, &B::stop_at_opening,
               &B::stability_tolerance, &B::shooting, &B::seed_profile, &B::site, &B::start_offset)
      .def_property("continuation", word_getter(&B::continuation), word_setter(&B::continuation, parse_continuation))
      .def_property("floquet_method", word_getter(&B::floquet_method),
                    word_setter(&B::floquet_method, parse_floquet_method))
      .def_readwrite("floquet_multipliers", &B::floquet_multipliers)
      .def_property("law", word_getter(&B::law), word_setter(&B::law, parse_force_law));  // not linear: _breathers.py
  using S = ShootingConfig;
  config_class(m, "ShootingConfig", "steps_per_period tolerance", &S::steps_per_period, &S::tolerance)
      .def_property(
          "scheme", [](const S& s) { return s.scheme.name; },
          [](S& s, const std::string& word) { s.scheme = parse_scheme(word); })
      .def_property("newton", word_getter(&S::newton), word_setter(&S::newton, parse_newton_method));
  m.def("_breathers", &breathers);
}

}  // namespace granular::python
