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

namespace granular::python {
namespace {

py::dict breathers(const PyChain& c, BreatherBranchConfig config) {
  config.chain = c.recipe;
  config.realization = c.realization;
  validate(config);
  BreatherBranch branch;
  {
    py::gil_scoped_release release;
    branch = continue_breather(config);
  }
  nlohmann::json meta = metadata_head("breathers");
  meta.update(describe_breather_branch(config, branch));
  const std::size_t points = branch.points.size(), n = c.chain.size();
  std::vector<double> omega, freq, energy, amplitude, max_mu, residual, open_max, profiles, open, mu_re, mu_im;
  std::vector<long long> centre, iterations;
  std::vector<std::uint8_t> stable;
  for (const auto& p : branch.points) {
    omega.push_back(p.omega), freq.push_back(p.freq_khz), energy.push_back(p.energy);
    amplitude.push_back(p.amplitude), max_mu.push_back(p.floquet.max_modulus), residual.push_back(p.residual);
    open_max.push_back(p.max_open_fraction), centre.push_back(static_cast<long long>(p.centre) + 1);
    iterations.push_back(p.iterations), stable.push_back(p.floquet.stable ? 1 : 0);
    profiles.insert(profiles.end(), p.x0.begin(), p.x0.end());
    open.insert(open.end(), p.open_fraction.begin(), p.open_fraction.end());
    for (const auto mu : p.floquet.multipliers) mu_re.push_back(mu.real()), mu_im.push_back(mu.imag());
  }
  py::dict out = fields(
      "omega freq_khz energy amplitude max_multiplier residual max_open_fraction centre "
      "newton_iterations stable linear_khz seed_mode seed_khz stop_reason",
      std::move(omega), std::move(freq), std::move(energy), std::move(amplitude), std::move(max_mu),
      std::move(residual), std::move(open_max), std::move(centre), std::move(iterations), std::move(stable),
      std::move(branch.linear_khz), branch.seed_mode, branch.seed_khz, branch.stop_reason);
  out["profiles"] = to_numpy_2d(std::move(profiles), points, n);
  out["open_fraction"] = to_numpy_2d(std::move(open), points, n + 1);
  out["multipliers_real"] = to_numpy_2d(std::move(mu_re), points, 2 * n);
  out["multipliers_imag"] = to_numpy_2d(std::move(mu_im), points, 2 * n);
  out["metadata"] = to_python(meta);
  return out;
}

}  // namespace

void bind_breathers(py::module_& m) {
  using B = BreatherBranchConfig;  // granular.breathers's keywords, its chain set from the granular.Chain
  config_class(m, "BreatherBranchConfig",
               "mode near_khz start_khz target_khz step_khz max_points stop_at_opening stability_tolerance shooting "
               "seed_profile",
               &B::mode, &B::near_khz, &B::start_khz, &B::target_khz, &B::step_khz, &B::max_points, &B::stop_at_opening,
               &B::stability_tolerance, &B::shooting, &B::seed_profile)
      .def_property(
          "continuation", [](const B& b) { return to_string(b.continuation); },
          [](B& b, const std::string& word) { b.continuation = parse_continuation(word); })
      .def_property(
          "law", [](const B& b) { return to_string(b.law); },
          [](B& b, const std::string& word) {
            b.law = parse_force_law(word);
            if (b.law == ForceLawKind::linear)
              bad_value("law", " linear: every amplitude is a periodic orbit; use hertz or fpu");
          });
  using S = ShootingConfig;
  config_class(m, "ShootingConfig", "steps_per_period tolerance", &S::steps_per_period, &S::tolerance)
      .def_property(
          "scheme", [](const S& s) { return s.scheme.name; },
          [](S& s, const std::string& word) { s.scheme = parse_scheme(word); });
  m.def("_breathers", &breathers);
}

}  // namespace granular::python
