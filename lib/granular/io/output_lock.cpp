#include "granular/io/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "granular/error.hpp"

namespace granular {

OutputLock::OutputLock(const std::string& prefix, const std::string& command) : path_(prefix + ".lock") {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw IoError("cannot create lock file '" + path_ + "': " + std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      char holder[512] = {};
      const ssize_t got = ::pread(fd, holder, sizeof holder - 1, 0);
      ::close(fd);
      std::string who = got > 0 ? std::string(holder, static_cast<std::size_t>(got)) : std::string("another process");
      while (!who.empty() && (who.back() == '\n' || who.back() == ' ')) who.pop_back();
      throw InvalidInput("output", " '" + prefix + "' is being written by " + who +
                                       "; wait for it to finish or choose another output");
    }
    // The holder we waited for may have removed the file after we opened it: lock what the path
    // names now, or try again.
    struct stat opened {
    }, named{};
    if (::fstat(fd, &opened) == 0 && ::stat(path_.c_str(), &named) == 0 && opened.st_ino == named.st_ino &&
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
