// slepc_nearest() in libgranular: forwards to the SLEPc component, loaded on first use (or built
// in, for a static libgranular), so that PETSc, SLEPc and MPI stay unloaded in every other run.
#include "granular/detail/component.hpp"
#include "granular/error.hpp"
#include "granular/linear/detail/shift_invert_eigensolvers.hpp"
#include "granular/linear/detail/slepc_component.hpp"

namespace granular {

#if GRANULAR_HAVE_SLEPC

bool have_slepc() { return true; }

ShiftInvertResult slepc_nearest(const SymTridiagonal& t, double sigma, const ShiftInvertConfig& config) {
#if GRANULAR_COMPONENTS_BUILT_IN
  static const detail::SlepcComponent* const component = granular_slepc_component();
#else
  using Entry = const detail::SlepcComponent* (*)();
  static const detail::SlepcComponent* const component =
      reinterpret_cast<Entry>(detail::component_entry("slepc", "granular_slepc_component", "the SLEPc method"))();
#endif
  return component->nearest(t, sigma, config);
}

#else  // no SLEPc in this build

bool have_slepc() { return false; }
ShiftInvertResult slepc_nearest(const SymTridiagonal&, double, const ShiftInvertConfig&) {
  throw InvalidInput("method", " slepc: this build has no SLEPc (configure with -DGRANULAR_WITH_SLEPC=ON)");
}

#endif

}  // namespace granular
