#include "granular/case/scheme_choice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "granular/case/time_step_rule.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/integrator.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/error.hpp"
#include "granular/model/chain.hpp"

namespace granular {

double srkn14a_default_step(double omega_max) {
  const double bound = srkn14a_accurate_omega_tau / omega_max;
  if (!(srkn14a_preferred_step > bound)) return srkn14a_preferred_step;
  return srkn14a_preferred_step / std::ceil(srkn14a_preferred_step / bound);
}

bool bonds_stay_closed(const TransportCase& c, const Chain* chain) {
  if (c.dynamics.integration.force_law != ForceLawKind::hertz) return true;
  if (!(c.chain.F0 > 0)) return false;
  const std::vector<Chain> chains = rule_chains(c, chain);
  const double energy = kick_energy_bound(c, chains, chain || !c.chain.drawn());
  double opening = std::numeric_limits<double>::infinity();
  for (const Chain& ch : chains) {
    const ForceLaw law = make_force_law(ForceLawKind::hertz, ch);
    for (std::size_t k = 0; k < ch.bonds(); ++k)
      opening = std::min(opening, std::visit([&](const auto& l) { return l.potential(k, -ch.overlap[k]); }, law));
  }
  return energy < opening;
}

SchemeChoice choose_scheme(double saba2c_step, double srkn14a_step, bool closed, bool damped) {
  const double cost = srkn14a_step_cost * saba2c_step / srkn14a_step;  // per simulated second, SABA2C = 1
  if (closed && !damped && cost < 1) return {"srkn14a", srkn14a_step, cost, closed, damped};
  return {"saba2c", saba2c_step, 1, closed, damped};
}

nlohmann::json to_json(const SchemeChoice& choice) {
  return {{"rule",
           "integrator auto: where no contact can open (the kick energy below every bond's opening energy) and "
           "nothing is damped (a damped step is a 2nd-order composition whatever the scheme), the "
           "cheapest of SRKN14a at 5e-6 s (or 5e-6/k s, keeping omega_max*tau <= 1.47 as in "
           "the benchmark) and SABA2C at its default step (else SABA2C), costing an SRKN14a step as 4.0 SABA2C steps; "
           "both keep the energy error at or below "
           "SABA2C's at 1e-6 s (docs/performance.md, cost-accuracy)"},
          {"integrator", choice.integrator},
          {"time_step_s", choice.time_step},
          {"relative_cost", choice.relative_cost},
          {"bonds_stay_closed", choice.bonds_stay_closed},
          {"damped", choice.damped}};
}

nlohmann::json settle_scheme_and_step(std::vector<TransportCase>& cases, const Chain* chain) {
  if (cases.empty() || !cases.front().automatic_integrator) return settle_time_step(cases, chain);
  if (cases.front().time_step)
    throw InvalidInput("dt", ": integrator auto chooses the time step too; leave it out or name a scheme");
  std::vector<TransportCase> trial = cases;  // SABA2C at its default step
  for (TransportCase& c : trial) c.dynamics.integration.integrator = saba2c();
  settle_time_step(trial, chain);
  double omega_max = 0;
  bool closed = true, damped = false;
  for (const TransportCase& c : trial) {
    omega_max = std::max(omega_max, time_step_limit(c, chain).omega_max);
    closed = closed && bonds_stay_closed(c, chain);
    damped = damped || c.dynamics.integration.damping.any();
  }
  const SchemeChoice choice =
      choose_scheme(trial.front().dynamics.integration.time_step, srkn14a_default_step(omega_max), closed, damped);
  for (TransportCase& c : cases) {
    c.dynamics.integration.integrator = parse_integrator(choice.integrator);
    c.time_step = choice.time_step;
    c.automatic_integrator = false;  // settled
  }
  nlohmann::json rule = settle_time_step(cases, chain);  // the chosen τ, checked against stability
  rule["time_step_given"] = false;
  rule["integrator_choice"] = to_json(choice);
  return rule;
}

nlohmann::json settle_scheme_and_step(TransportCase& c, const Chain* chain) {
  std::vector<TransportCase> one{c};
  nlohmann::json rule = settle_scheme_and_step(one, chain);
  c = one.front();
  return rule;
}

}  // namespace granular
