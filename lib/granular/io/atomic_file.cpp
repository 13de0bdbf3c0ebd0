#include "granular/io/atomic_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "granular/error.hpp"

namespace granular {

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  check_writable(path_);
  temporary_ = path_ + ".tmp." + std::to_string(::getpid());
  out_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) throw IoError("cannot create '" + temporary_ + "'");
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(temporary_.c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw IoError("writing '" + temporary_ + "' failed");
  out_.close();
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) throw IoError("cannot rename '" + temporary_ + "' to '" + path_ + "'");
  committed_ = true;
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
  std::FILE* f = std::fopen(probe.c_str(), "wb");
  if (!f) throw IoError("output folder '" + folder.string() + "' is not writable");
  std::fclose(f);
  fs::remove(probe, ec);
}

void write_file_atomically(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace granular
