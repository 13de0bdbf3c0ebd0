#pragma once
// The entry point of the SLEPc component (libgranular_slepc.so, or built into a static
// libgranular): slepc_nearest() in libgranular calls it, so only runs of the SLEPc method load
// PETSc, SLEPc and MPI (detail/component.hpp).
#include "granular/linear/detail/shift_invert_eigensolvers.hpp"

namespace granular::detail {

/// What the component provides; a table, so that one symbol is looked up.
struct SlepcComponent {
  /// slepc_nearest() itself: collective over MPI_COMM_WORLD, starts SLEPc on first use and
  /// ends it at exit.
  ShiftInvertResult (*nearest)(const SymTridiagonal& t, double sigma, const ShiftInvertConfig& config);
  /// The same for a sparse symmetric matrix (each rank assembles the rows it owns).
  ShiftInvertResult (*nearest_sparse)(const SparseSymmetric& a, double sigma, const ShiftInvertConfig& config);
  /// slepc_window(): every eigenpair of a sparse symmetric matrix in [lo, hi], by spectrum slicing.
  ShiftInvertResult (*window_sparse)(const SparseSymmetric& a, double lo, double hi);
};

}  // namespace granular::detail

/// The component's table (C linkage: the name dlsym looks up).
extern "C" const granular::detail::SlepcComponent* granular_slepc_component();
