#include "granular/dynamics/integrator.hpp"

#include <cctype>

#include "granular/error.hpp"

namespace granular {

Integrator Integrator::odeint(const ReferenceTolerance& tolerance) {
  Integrator i;
  i.reference = true;
  i.tolerance = tolerance;
  return i;
}

Integrator parse_integrator(std::string_view name) {
  std::string lower(name);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "reference") return Integrator::odeint();
  if (lower == "saba2c" || lower == "saba2" || lower == "aba864" || lower == "srkn14a") return parse_scheme(lower);
  throw InvalidInput("integrator", " '" + std::string(name) + "': expected saba2c, saba2, aba864, srkn14a or reference");
}

std::unique_ptr<Propagator> make_propagator(const Integrator& integrator, const ForceLaw& law, const Chain& chain,
                                            double time_step, const State& initial, const ActiveWindow& window) {
  if (integrator.reference) return make_reference_propagator(law, chain, time_step, initial, integrator.tolerance);
  return make_splitting_propagator(law, chain, integrator.scheme, time_step, initial, window);
}

}  // namespace granular
