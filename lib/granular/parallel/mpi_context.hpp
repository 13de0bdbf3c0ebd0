#pragma once
// The MPI world a process runs in, and the one place that starts MPI: rank 0 of 1 when MPI is
// absent from the build or the process was not started by mpirun. MPI is initialized at most once
// per process (MPI_Init_thread, FUNNELED: only the main thread talks MPI while OpenMP workers
// compute) and finalized at exit. Ensembles spread realizations over the ranks; SLEPc (linear/)
// asks for MPI through require() and so never starts or ends it itself.
#include <cstdint>
#include <vector>

namespace granular {

class MpiContext {
 public:
  /// The world; starts MPI if the build has it and mpirun launched this process (a plain process
  /// stays a single rank without loading MPI: libgranular calls it through its MPI component).
  static MpiContext& instance();
  /// Starts MPI even outside mpirun (a singleton world of one rank), for libraries that need an
  /// initialized MPI (PETSc/SLEPc). Idempotent; a no-op without MPI in the build. Throws IoError
  /// when the MPI component (libgranular_mpi.so) does not load.
  void require();
  /// Whether MPI is initialized (by this class) and not yet finalized.
  bool active() const { return active_; }

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }

  /// Every rank contributes (index, values) records; rank 0 receives all of them, the other ranks
  /// an empty result. Records are returned indexed by their `index`.
  std::vector<std::vector<double>> gather_rows(std::size_t total, const std::vector<std::uint64_t>& indices,
                                               const std::vector<std::vector<double>>& rows) const;

  /// Logical AND of a flag over all ranks (an error on any rank stops every rank).
  bool all(bool flag) const;

 private:
  MpiContext();
  ~MpiContext();
  void start();
  int rank_ = 0, size_ = 1;
  bool initialized_here_ = false, active_ = false;
};

}  // namespace granular
