#include "granular/io/detail/temporary_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "granular/error.hpp"
#include "granular/io/atomic_file.hpp"

namespace granular::detail {

namespace {

std::string cause(int error) { return error ? std::string(": ") + std::strerror(error) : std::string(); }

int create_new(const std::string& path) {
  return ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
}

}  // namespace

TemporaryFile::TemporaryFile(std::string target, const std::string& kind) : target_(std::move(target)) {
  check_writable(target_);
  path_ = target_ + ".tmp." + std::to_string(::getpid());
  fd_ = create_new(path_);
  // A leftover of a killed run that had the same pid: unlinked (a symlink itself, not its target).
  if (fd_ < 0 && errno == EEXIST && ::unlink(path_.c_str()) == 0) fd_ = create_new(path_);
  if (fd_ < 0) throw IoError("cannot create " + kind + "'" + path_ + "'" + cause(errno));
}

TemporaryFile::~TemporaryFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) std::remove(path_.c_str());
}

void TemporaryFile::commit() {
  // Every step can fail on a full or broken disk; the message says which file and why. Until the
  // rename the target is untouched, and the temporary file goes with the destructor.
  // Named by the file the user asked for: the temporary name is never seen (it goes with the destructor).
  int error = ::fsync(fd_) == 0 ? 0 : errno;
  if (::close(fd_) != 0 && !error) error = errno;
  fd_ = -1;
  if (error) throw IoError("writing '" + target_ + "' failed" + cause(error));
  rename_and_sync_folder();
}

int TemporaryFile::commit_open() {
  if (::fsync(fd_) != 0) throw IoError("writing '" + target_ + "' failed" + cause(errno));
  rename_and_sync_folder();
  const int fd = fd_;
  fd_ = -1;
  return fd;
}

void TemporaryFile::rename_and_sync_folder() {
  if (std::rename(path_.c_str(), target_.c_str()) != 0)
    throw IoError("cannot rename '" + path_ + "' to '" + target_ + "'" + cause(errno));
  committed_ = true;
  // The rename itself is durable only once the folder is synced.
  const std::filesystem::path folder = std::filesystem::path(target_).parent_path();
  const int dir = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  int error = dir < 0 ? errno : ::fsync(dir) == 0 ? 0 : errno;
  if (dir >= 0 && ::close(dir) != 0 && !error) error = errno;
  if (error) throw IoError("flushing the folder of '" + target_ + "' to disk failed" + cause(error));
}

}  // namespace granular::detail
