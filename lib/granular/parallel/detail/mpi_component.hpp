#pragma once
// The entry point of the MPI component (libgranular_mpi.so, or built into a static libgranular):
// MpiContext calls MPI through it, so that a process not started by mpirun (nor using SLEPc,
// which loads MPI itself) does not load Open MPI and the libraries it brings (detail/component.hpp).
#include <vector>

namespace granular::detail {

/// What the component provides; a table, so that one symbol is looked up.
struct MpiComponent {
  /// MPI_Initialized.
  bool (*initialized)();
  /// MPI_Finalized.
  bool (*finalized)();
  /// MPI_Init_thread with MPI_THREAD_FUNNELED (only the main thread talks MPI).
  void (*init)();
  /// MPI_Finalize.
  void (*finalize)();
  /// This process's rank and the size of MPI_COMM_WORLD.
  void (*world)(int* rank, int* size);
  /// Every rank's `send` concatenated in rank order into `received` on rank 0 (MPI_Gatherv).
  void (*gather)(const std::vector<double>& send, std::vector<double>& received);
  /// Logical AND of `flag` over MPI_COMM_WORLD (MPI_Allreduce).
  bool (*all)(bool flag);
};

}  // namespace granular::detail

/// The component's table (C linkage: the name dlsym looks up).
extern "C" const granular::detail::MpiComponent* granular_mpi_component();
