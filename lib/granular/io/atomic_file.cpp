#include "granular/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <streambuf>
#include <vector>

#include "granular/error.hpp"

namespace granular {

namespace {

std::string cause(int error) { return error ? std::string(": ") + std::strerror(error) : std::string(); }

/// fsync of a file or folder by path; the errno of the failure, or 0.
int sync_path(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return errno;
  const int result = ::fsync(fd) == 0 ? 0 : errno;
  return ::close(fd) == 0 ? result : (result ? result : errno);
}

}  // namespace

/// A stream buffer over a file descriptor that keeps the errno of the first failed write (an
/// ofstream loses it: by the time a caller looks, errno says nothing about the disk).
class AtomicFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(int fd) : fd_(fd), data_(1 << 16) { setp(data_.data(), data_.data() + data_.size()); }
  ~Buffer() override {
    if (fd_ >= 0) ::close(fd_);
  }
  int error() const { return error_; }
  /// Writes what is buffered, fsyncs and closes; the errno of the first failure, or 0.
  int finish() {
    sync();
    if (!error_ && ::fsync(fd_) != 0) error_ = errno;
    if (::close(fd_) != 0 && !error_) error_ = errno;
    fd_ = -1;
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

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), out_(nullptr) {
  check_writable(path_);
  temporary_ = path_ + ".tmp." + std::to_string(::getpid());
  const int fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw IoError("cannot create '" + temporary_ + "'" + cause(errno));
  buffer_ = std::make_unique<Buffer>(fd);
  out_.rdbuf(buffer_.get());
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.rdbuf(nullptr);
    buffer_.reset();
    std::remove(temporary_.c_str());
  }
}

void AtomicFile::commit() {
  // Every step can fail on a full or broken disk; the message says which file and why. Until the
  // rename the target is untouched, and the temporary file goes with the destructor.
  // Named by the file the user asked for: the temporary name is never seen (it goes with the destructor).
  if (const int e = buffer_->finish()) throw IoError("writing '" + path_ + "' failed" + cause(e));
  if (!out_) throw IoError("writing '" + path_ + "' failed" + cause(EIO));
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0)
    throw IoError("cannot rename '" + temporary_ + "' to '" + path_ + "'" + cause(errno));
  committed_ = true;
  // The rename itself is durable only once the folder is synced.
  std::filesystem::path folder = std::filesystem::path(path_).parent_path();
  if (const int e = sync_path(folder.empty() ? "." : folder.string(), O_RDONLY | O_DIRECTORY))
    throw IoError("flushing the folder of '" + path_ + "' to disk failed" + cause(e));
}

void check_writable(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw IoError("empty output path");
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw IoError("output folder '" + folder.string() + "' does not exist");
  if (fs::is_directory(path, ec)) throw IoError("output path '" + path + "' is a folder");
  // access(W_OK) says yes to root on a read-only mount: create and remove a probe instead.
  const fs::path probe = folder / (".granular-probe." + std::to_string(::getpid()));
  errno = 0;
  std::FILE* f = std::fopen(probe.c_str(), "wb");
  if (!f) throw IoError("output folder '" + folder.string() + "' is not writable" + cause(errno));
  std::fclose(f);
  fs::remove(probe, ec);
}

void write_file_atomically(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace granular
