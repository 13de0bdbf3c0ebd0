#include "granular/io/atomic_file.hpp"

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <streambuf>
#include <vector>

#include "granular/error.hpp"
#include "granular/io/detail/temporary_file.hpp"

namespace granular {

namespace {

std::string cause(int error) { return error ? std::string(": ") + std::strerror(error) : std::string(); }

}  // namespace

/// A stream buffer over a file descriptor (not owned) that keeps the errno of the first failed
/// write (an ofstream loses it: by the time a caller looks, errno says nothing about the disk).
class AtomicFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(int fd) : fd_(fd), data_(1 << 16) { setp(data_.data(), data_.data() + data_.size()); }
  /// Writes what is buffered; the errno of the first failure, or 0.
  int finish() {
    sync();
    return error_;
  }

 protected:
  int_type overflow(int_type c) override {
    if (sync() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override {
    const char* p = pbase();
    while (!error_ && p < pptr()) {
      const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(pptr() - p));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) error_ = n < 0 ? errno : EIO;
      else p += n;
    }
    setp(data_.data(), data_.data() + data_.size());
    return error_ ? -1 : 0;
  }

 private:
  int fd_;
  int error_ = 0;
  std::vector<char> data_;
};

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), temporary_(std::make_unique<detail::TemporaryFile>(path_)), out_(nullptr) {
  buffer_ = std::make_unique<Buffer>(temporary_->fd());
  out_.rdbuf(buffer_.get());
}

AtomicFile::~AtomicFile() { out_.rdbuf(nullptr); }

void AtomicFile::commit() {
  // Named by the file the user asked for: the temporary name is never seen (it goes with the destructor).
  if (const int e = buffer_->finish()) throw IoError("writing '" + path_ + "' failed" + cause(e));
  if (!out_) throw IoError("writing '" + path_ + "' failed" + cause(EIO));
  temporary_->commit();  // fsync, rename onto path_, fsync of the folder
}

void check_writable(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw IoError("empty output path");
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw IoError("output folder '" + folder.string() + "' does not exist");
  if (fs::is_directory(path, ec)) throw IoError("output path '" + path + "' is a folder");
  // access(W_OK) says yes to root on a read-only mount: create and remove a probe instead. The
  // probe is a new file (O_EXCL | O_NOFOLLOW) under a name nobody can guess, so nothing planted in
  // the folder can make it open, truncate or remove another file.
  std::string probe = (folder / ".granular-probe.XXXXXX").string();
  errno = 0;
  const int fd = ::mkostemp(probe.data(), O_CLOEXEC);  // O_CREAT | O_EXCL, a random name
  if (fd < 0) throw IoError("output folder '" + folder.string() + "' is not writable" + cause(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

void write_file_atomically(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace granular
