#pragma once
// One writer per output. A run holds an advisory lock (flock) on PREFIX.lock while it writes
// PREFIX's outputs and checkpoints; a second run on the same prefix is refused, naming the process
// that holds it, so neither corrupts the other. The kernel drops the lock when its process dies:
// a killed run never blocks the resume that follows it.
#include <string>

namespace granular {

class OutputLock {
 public:
  /// Locks `prefix` + ".lock" (created if needed; the holder's pid and `command` are written in
  /// it). Throws InvalidInput naming `output` and the holding process when another run holds it,
  /// IoError when the lock file cannot be created.
  explicit OutputLock(const std::string& prefix, const std::string& command = "");
  ~OutputLock();  ///< releases the lock and removes the file
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace granular
