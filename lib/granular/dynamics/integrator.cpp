#include "granular/dynamics/integrator.hpp"

#include "granular/detail/enum_names.hpp"
#include "granular/error.hpp"

namespace granular {

Integrator Integrator::odeint(const ReferenceTolerance& tolerance) {
  Integrator i;
  i.reference = true;
  i.tolerance = tolerance;
  return i;
}

Integrator parse_integrator(std::string_view name) {
  static constexpr auto names =
      detail::enum_names<Integrator (*)()>("integrator",
                                           {{[] { return Integrator(saba2c()); }, "saba2c"},
                                            {[] { return Integrator(saba2()); }, "saba2"},
                                            {[] { return Integrator(aba864()); }, "aba864"},
                                            {[] { return Integrator(srkn14a()); }, "srkn14a"},
                                            {[] { return Integrator::odeint(); }, "reference"}},
                                           true);
  return names.parse(name)();
}

std::unique_ptr<Propagator> make_propagator(const Integrator& integrator, const ForceLaw& law, const Chain& chain,
                                            double time_step, const State& initial, const ActiveWindow& window) {
  if (integrator.reference) return make_reference_propagator(law, chain, time_step, initial, integrator.tolerance);
  return make_splitting_propagator(law, chain, integrator.scheme, time_step, initial, window);
}

}  // namespace granular
