#pragma once
// The temporary file behind every output that appears whole or not at all (AtomicFile, Hdf5File):
// PATH.tmp.<pid> beside the target, created new with O_CREAT | O_EXCL | O_NOFOLLOW (never through
// a symlink, never into a file that exists: a leftover of that name, from a killed run with the
// same pid, is unlinked first and the creation retried once), removed by the destructor unless
// committed. commit() fsyncs and closes it, renames it onto the target and fsyncs the folder.
#include <string>

namespace granular::detail {

class TemporaryFile {
 public:
  /// Checks that `target`'s folder is writable (check_writable) and creates the temporary file;
  /// throws IoError "cannot create <kind>'PATH.tmp.<pid>': cause".
  explicit TemporaryFile(std::string target, const std::string& kind = "");
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  /// Closes the descriptor and, unless committed, removes the temporary file.
  ~TemporaryFile();

  int fd() const { return fd_; }  ///< open for writing until commit()
  const std::string& path() const { return path_; }
  const std::string& target() const { return target_; }

  /// Fsyncs and closes the file, renames it onto the target and fsyncs the folder. Throws IoError
  /// naming the target ("writing 'out.csv' failed: No space left on device").
  void commit();
  /// As commit(), but the descriptor stays open (now on the target) and passes to the caller, who
  /// closes it: appending through it never reopens the target by name (a log written on after
  /// its header is committed).
  int commit_open();

 private:
  void rename_and_sync_folder();
  std::string target_, path_;
  int fd_ = -1;
  bool committed_ = false;
};

}  // namespace granular::detail
