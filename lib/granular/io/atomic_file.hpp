#pragma once
// An output file that appears whole or not at all: written to a temporary name beside the
// target and renamed over it on commit(). Destroyed without commit(), it leaves no trace, so
// an error or an interrupted run never leaves a partial or truncated output.
#include <memory>
#include <ostream>
#include <string>

#include "granular/io/pending_output.hpp"

namespace granular {

namespace detail {
class TemporaryFile;
}

class AtomicFile : public PendingOutput {
 public:
  explicit AtomicFile(std::string path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile() override;

  std::ostream& stream() { return out_; }
  /// Flushes, closes and fsyncs the file, renames it onto the target and fsyncs the folder;
  /// throws IoError naming the file and the cause ("No space left on device") on failure.
  void commit() override;
  const std::string& path() const { return path_; }

 private:
  class Buffer;  // writes through to the file descriptor and remembers the first errno
  std::string path_;
  std::unique_ptr<detail::TemporaryFile> temporary_;  // PATH.tmp.<pid>, removed unless committed
  std::unique_ptr<Buffer> buffer_;
  std::ostream out_;
};

/// Throws IoError unless `path`'s folder exists and is writable (checked before long work).
void check_writable(const std::string& path);

/// Writes `text` to `path` atomically.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace granular
