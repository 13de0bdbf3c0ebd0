#include "granular/io/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "granular/error.hpp"

namespace granular {

namespace {

/// The first line of what the holder wrote, at most 200 bytes, non-printable bytes as \xNN: a
/// lock file anyone could have written is never echoed raw onto a terminal.
std::string excerpt(const char* text, std::size_t size) {
  std::string out;
  std::size_t i = 0;
  for (; i < size && i < 200 && text[i] != '\n'; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out.push_back(static_cast<char>(c));
    } else {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
    }
  }
  if (i < size && text[i] != '\n') out += "...";
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

}  // namespace

OutputLock::OutputLock(const std::string& prefix, const std::string& command) : path_(prefix + ".lock") {
  for (int attempt = 0; attempt < 100; ++attempt) {
    // O_NOFOLLOW: a symlink planted at PREFIX.lock is refused, never followed into a file we would truncate.
    const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) {
      const int e = errno;
      struct stat link {};
      if (e == ELOOP || (::lstat(path_.c_str(), &link) == 0 && S_ISLNK(link.st_mode)))
        throw InvalidInput("output", " '" + prefix + "': '" + path_ +
                                         "' is a symbolic link, not a lock file; remove it or choose another output");
      throw IoError("cannot create lock file '" + path_ + "': " + std::strerror(e));
    }
    struct stat opened {};
    // A hard link to another file would be truncated below as surely as a symlink's target.
    if (::fstat(fd, &opened) != 0 || !S_ISREG(opened.st_mode) || opened.st_nlink != 1) {
      ::close(fd);
      throw InvalidInput("output", " '" + prefix + "': '" + path_ +
                                       "' is not a lock file of its own (not a regular file, or a link to "
                                       "another); remove it or choose another output");
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      char holder[512] = {};
      const ssize_t got = ::pread(fd, holder, sizeof holder, 0);
      ::close(fd);
      const std::string who = got > 0 ? excerpt(holder, static_cast<std::size_t>(got)) : std::string();
      throw InvalidInput("output", " '" + prefix + "' is being written by " + (who.empty() ? "another process" : who) +
                                       "; wait for it to finish or choose another output");
    }
    // The holder we waited for may have removed the file after we opened it: lock what the path
    // names now, or try again. lstat, not stat: a symlink put there since names another file.
    struct stat named {};
    if (::lstat(path_.c_str(), &named) == 0 && S_ISREG(named.st_mode) && opened.st_ino == named.st_ino &&
        opened.st_dev == named.st_dev) {
      const std::string text =
          "process " + std::to_string(::getpid()) + (command.empty() ? "" : " (" + command + ")") + "\n";
      if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size())) {
        const int e = errno;
        ::close(fd);
        throw IoError("cannot write lock file '" + path_ + "': " + std::strerror(e));
      }
      fd_ = fd;
      return;
    }
    ::close(fd);
  }
  throw IoError("cannot lock '" + path_ + "': it keeps being replaced");
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // while still holding the lock: a waiter re-checks the inode
  ::close(fd_);
}

}  // namespace granular
