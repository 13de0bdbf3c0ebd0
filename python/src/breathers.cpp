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

py::dict breathers(const py::object& chain, long mode, double near_khz, double start_khz, double target_khz,
                   double step_khz, long long max_points, const std::string& law, const std::string& scheme,
                   long long steps_per_period, double tolerance, double stability_tolerance, bool through_opening) {
  if (!py::isinstance<PyChain>(chain)) throw py::type_error("chain: expected a granular.Chain");
  const PyChain& c = chain.cast<const PyChain&>();
  BreatherBranchConfig config;
  config.chain = c.recipe;
  config.realization = c.realization;
  config.mode = mode;
  config.near_khz = near_khz, config.start_khz = start_khz, config.target_khz = target_khz;
  config.step_khz = step_khz;
  config.max_points = checked_size(max_points, "max_points", 1, 1000000);
  config.law = parse_force_law(law);
  if (config.law == ForceLawKind::linear)
    bad_value("law", " linear: every amplitude is a periodic orbit; use hertz or fpu");
  config.shooting.scheme = parse_scheme(scheme);
  config.shooting.steps_per_period = checked_size(steps_per_period, "steps_per_period", 0, 100000000);
  config.shooting.tolerance = finite(tolerance, "tolerance");
  config.stability_tolerance = finite(stability_tolerance, "stability_tolerance");
  config.stop_at_opening = !through_opening;
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
  py::dict out;
  put(out, {{"omega", &omega},
            {"freq_khz", &freq},
            {"energy", &energy},
            {"amplitude", &amplitude},
            {"max_multiplier", &max_mu},
            {"residual", &residual},
            {"max_open_fraction", &open_max}});
  out["centre"] = to_numpy(std::move(centre));
  out["newton_iterations"] = to_numpy(std::move(iterations));
  out["stable"] = to_numpy(std::move(stable));
  out["profiles"] = to_numpy_2d(std::move(profiles), points, n);
  out["open_fraction"] = to_numpy_2d(std::move(open), points, n + 1);
  out["multipliers_real"] = to_numpy_2d(std::move(mu_re), points, 2 * n);
  out["multipliers_imag"] = to_numpy_2d(std::move(mu_im), points, 2 * n);
  out["linear_khz"] = to_numpy(branch.linear_khz);
  out["seed_mode"] = branch.seed_mode;
  out["seed_khz"] = branch.seed_khz;
  out["stop_reason"] = branch.stop_reason;
  out["metadata"] = to_python(meta);
  return out;
}

}  // namespace

void bind_breathers(py::module_& m) { m.def("_breathers", &breathers); }

}  // namespace granular::python
