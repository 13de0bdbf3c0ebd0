#pragma once
// What a run does before it touches any file of its output prefix: it takes PREFIX.lock (one
// writer per output, io/output_lock.hpp), then whatever else the caller must settle while no
// other run can interfere (e.g. refuse to start afresh over an interrupted run's checkpoint).
// Under MPI, rank 0 alone claims; every rank learns whether it could, so all go on or all stop.
#include <functional>
#include <optional>
#include <string>

#include "granular/io/output_lock.hpp"

namespace granular {

/// Thrown on the MPI ranks other than 0 when rank 0 could not claim the prefix (rank 0 throws the
/// reason itself, and says it): `refused` when rank 0 was refused (InvalidInput: another run owns
/// the output, or the caller's check said no), else it could not write (IoError and the rest).
struct ClaimFailedOnRoot {
  bool refused;
};

class OutputClaim {
 public:
  /// Claims `prefix` for this run (`command` goes into the lock file, for whoever is refused),
  /// then runs `then` on rank 0 while holding it. Throws what failed on rank 0 (InvalidInput when
  /// another run holds the prefix, IoError when its folder cannot be written), ClaimFailedOnRoot
  /// on the other ranks. The lock is held until this object is destroyed.
  OutputClaim(const std::string& prefix, const std::string& command, const std::function<void()>& then = {});

 private:
  std::optional<OutputLock> lock_;
};

}  // namespace granular
