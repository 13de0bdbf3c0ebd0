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
  static const detail::SlepcComponent* const component =
      GRANULAR_COMPONENT_TABLE(detail::SlepcComponent, slepc, "the SLEPc method");
  return component->nearest(t, sigma, config);
}

ShiftInvertResult slepc_nearest(const SparseSymmetric& a, double sigma, const ShiftInvertConfig& config) {
  static const detail::SlepcComponent* const component =
      GRANULAR_COMPONENT_TABLE(detail::SlepcComponent, slepc, "the SLEPc method");
  return component->nearest_sparse(a, sigma, config);
}

ShiftInvertResult slepc_window(const SparseSymmetric& a, double lo, double hi) {
  static const detail::SlepcComponent* const component =
      GRANULAR_COMPONENT_TABLE(detail::SlepcComponent, slepc, "the SLEPc method");
  return component->window_sparse(a, lo, hi);
}

#else  // no SLEPc in this build

bool have_slepc() { return false; }
ShiftInvertResult slepc_nearest(const SymTridiagonal&, double, const ShiftInvertConfig&) {
  throw InvalidInput("method", " slepc: this build has no SLEPc (configure with -DGRANULAR_WITH_SLEPC=ON)");
}
ShiftInvertResult slepc_nearest(const SparseSymmetric&, double, const ShiftInvertConfig&) {
  throw InvalidInput("method", " slepc: this build has no SLEPc (configure with -DGRANULAR_WITH_SLEPC=ON)");
}
ShiftInvertResult slepc_window(const SparseSymmetric&, double, double) {
  throw InvalidInput("method", " slepc: this build has no SLEPc (configure with -DGRANULAR_WITH_SLEPC=ON)");
}

#endif

}  // namespace granular
