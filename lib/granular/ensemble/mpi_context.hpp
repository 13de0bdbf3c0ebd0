#pragma once
// The MPI world a tool runs in: rank 0 of 1 when MPI is absent from the build or the tool was
// not started by mpirun. Initialized once per process (MPI_Init_thread, FUNNELED: only the main
// thread talks MPI while OpenMP workers compute), finalized at exit.
#include <cstdint>
#include <vector>

namespace granular {

class MpiContext {
 public:
  /// Initializes MPI if the build has it (idempotent; safe when not under mpirun).
  static MpiContext& instance();

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
  int rank_ = 0, size_ = 1;
  bool initialized_here_ = false;
};

}  // namespace granular
