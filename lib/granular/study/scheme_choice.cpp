#include "granular/study/scheme_choice.hpp"

namespace granular {

SchemeChoice choose_scheme(double saba2c_step, double srkn14a_step) {
  const double cost = srkn14a_step_cost * saba2c_step / srkn14a_step;  // per simulated second, SABA2C = 1
  if (cost < 1) return {"srkn14a", srkn14a_step, cost};
  return {"saba2c", saba2c_step, 1};
}

nlohmann::json to_json(const SchemeChoice& choice) {
  return {{"rule",
           "--integrator auto: the cheapest of SRKN14a at 5e-6 s (or 5e-6/k s by the stability rule) and SABA2C at "
           "its default step, costing an SRKN14a step as 4.0 SABA2C steps; both keep the energy error at or below "
           "SABA2C's at 1e-6 s (docs/dynamics-performance.md, cost-accuracy)"},
          {"integrator", choice.integrator},
          {"time_step_s", choice.time_step},
          {"relative_cost", choice.relative_cost}};
}

}  // namespace granular
