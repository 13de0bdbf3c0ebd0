#include "granular/case/case_settling.hpp"

#include <nlohmann/json.hpp>

#include "granular/case/chain_length_rule.hpp"
#include "granular/case/scheme_choice.hpp"

namespace granular {

nlohmann::json validate_and_settle(std::vector<TransportCase>& cases, const std::string& duration_option,
                                   std::string& warning, const Chain* chain) {
  for (const TransportCase& c : cases) validate_before_time_step(c);
  nlohmann::json rule = settle_scheme_and_step(cases, chain);
  for (TransportCase& c : cases) {
    validate(c);                  // on the settled τ's grid
    c.site = kicked_bead(c) + 1;  // the centre's number where 0 stood for it: the JSON names the bead
  }
  // The rule's ω_max: the largest of the cases (a bound for each), as settle_time_step found it.
  const double omega_max = rule.at("omega_max_rad_s").get<double>();
  warning.clear();
  for (const TransportCase& c : cases)
    if (!(warning = duration_warning(c, omega_max, duration_option)).empty()) break;
  return rule;
}

nlohmann::json validate_and_settle(TransportCase& c, const std::string& duration_option, std::string& warning,
                                   const Chain* chain) {
  std::vector<TransportCase> one{c};
  nlohmann::json rule = validate_and_settle(one, duration_option, warning, chain);
  c = one.front();
  return rule;
}

}  // namespace granular
