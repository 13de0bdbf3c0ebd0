#include "granular/klein_gordon/klein_gordon_study.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "granular/parameter_json.hpp"

namespace granular {

KleinGordonResult klein_gordon_study(const KleinGordonCase& c) {
  validate(c);
  KleinGordonResult r;
  const KleinGordonRunConfig config = run_config(c);
  r.sample_steps = config.sample_steps;
  r.ensemble = klein_gordon_ensemble(config, c.realizations, c.threads);
  for (const KleinGordonRun& run : r.ensemble.runs)
    r.max_energy_error = std::max(r.max_energy_error, run.max_energy_error);
  if (c.fit.size() == 2) r.exponents = klein_gordon_exponents(r.ensemble, c.fit[0], c.fit[1]);
  return r;
}

nlohmann::json describe(const KleinGordonCase& c, const KleinGordonResult& r) {
  nlohmann::json meta;
  meta["parameters"] = describe_rows(c, klein_gordon_parameters());
  meta["model"] =
      "disordered Klein-Gordon chain, H = sum p^2/2 + e_l x^2/2 + x^4/4 + (x_{l+1} - x_l)^2/(2W), "
      "fixed ends; time in 1/omega0, energy in units of H (docs/physics.md)";
  meta["scheme"] = "SABA2C";
  meta["samples"] = {{"rule", klein_gordon_sample_rule}, {"count", r.sample_steps.size()}};
  meta["observables"] = {
      {"m2", "sum (l - centroid)^2 z_l, z_l = E_l / sum E [sites^2]"},
      {"P", "participation number 1 / sum z_l^2 [sites]"},
      {"mle", "finite-time mLE Lambda(t) = X1(t) [omega0]: deviation on the centre site, renormalized every 10 steps"},
      {"mean_log10_mle", "<log10 Lambda> over the realizations"}};
  meta["realizations"] = r.ensemble.runs.size();
  meta["max_energy_error"] = r.max_energy_error;
  if (r.exponents) meta["exponents"] = describe(*r.exponents, r.ensemble.runs.size(), !r.ensemble.mle.empty());
  return meta;
}

}  // namespace granular
