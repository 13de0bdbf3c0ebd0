#include "granular/io/hdf5_file.hpp"

#include "granular/detail/component.hpp"
#include "granular/error.hpp"
#include "granular/io/detail/hdf5_component.hpp"
#include "granular/io/detail/temporary_file.hpp"

namespace granular {

namespace detail {

const Hdf5Component& hdf5_component() {
  static const Hdf5Component* const component = GRANULAR_COMPONENT_TABLE(Hdf5Component, hdf5, "writing HDF5");
  return *component;
}

}  // namespace detail

void load_hdf5_writer() { static_cast<void>(detail::hdf5_component()); }

Hdf5File::Hdf5File(std::string path) : path_(std::move(path)) {
  // Before the temporary file: a missing component leaves nothing behind.
  const detail::Hdf5Component& hdf5 = detail::hdf5_component();
  temporary_ = std::make_unique<detail::TemporaryFile>(path_, "HDF5 file ");
  // HDF5 opens files by name, and a name in a shared folder can be swapped for a symlink after
  // the temporary file was created: open the file we created itself, through its descriptor.
  const std::string own = "/proc/self/fd/" + std::to_string(temporary_->fd());
  file_ = hdf5.create(own, temporary_->path());
}

Hdf5File::~Hdf5File() {
  if (file_ >= 0) detail::hdf5_component().discard(file_);
}

void Hdf5File::write(const std::string& name, const double* data, std::size_t rows, std::size_t cols) {
  detail::hdf5_component().write_doubles(file_, name, data, rows, cols, path_);  // named as the user asked
}

void Hdf5File::write(const std::string& name, const std::vector<std::uint64_t>& data) {
  detail::hdf5_component().write_uint64(file_, name, data.data(), data.size(), path_);
}

void Hdf5File::attribute(const std::string& name, const std::string& value) {
  detail::hdf5_component().attribute(file_, name, value, path_);
}

void Hdf5File::commit() {
  const long long file = file_;
  file_ = -1;
  detail::hdf5_component().close(file, path_);
  temporary_->commit();  // fsync, rename onto path_, fsync of the folder
}

void write_hdf5_atomically(const std::string& path, const std::vector<Hdf5Array>& arrays) {
  Hdf5File file(path);
  for (const Hdf5Array& a : arrays) {
    if (a.shape.empty() || a.shape.size() > 2) throw IoError("HDF5 dataset '" + a.name + "': only 1-D and 2-D arrays");
    file.write(a.name, a.data, a.shape[0], a.shape.size() == 2 ? a.shape[1] : 1);
  }
  file.commit();
}

}  // namespace granular
