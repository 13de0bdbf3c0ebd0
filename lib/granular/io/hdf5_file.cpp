#include "granular/io/hdf5_file.hpp"

#include <cerrno>
#include <cstring>

#include <hdf5.h>

#include "granular/error.hpp"
#include "granular/io/detail/temporary_file.hpp"

namespace granular {

namespace {

/// HDF5 prints its whole internal error stack on stderr by default; failures here become one
/// IoError naming the file and the system's cause instead.
void silence_hdf5() {
  static const bool silenced = [] { return H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) >= 0; }();
  (void)silenced;
}

/// ": No space left on device" when the C library recorded why; "" otherwise.
std::string cause() { return errno ? std::string(": ") + std::strerror(errno) : std::string(); }

}  // namespace

Hdf5File::Hdf5File(std::string path) : path_(std::move(path)) {
  silence_hdf5();
  temporary_ = std::make_unique<detail::TemporaryFile>(path_, "HDF5 file ");
  errno = 0;
  // HDF5 opens files by name, and a name in a shared folder can be swapped for a symlink after
  // the temporary file was created: open the file we created itself, through its descriptor.
  const std::string own = "/proc/self/fd/" + std::to_string(temporary_->fd());
  file_ = H5Fcreate(own.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw IoError("cannot create HDF5 file '" + temporary_->path() + "'" + cause());
}

Hdf5File::~Hdf5File() {
  if (file_ >= 0) H5Fclose(file_);
}

namespace {

void write_dataset(hid_t file, const std::string& name, hid_t type, const void* data, std::size_t rows,
                   std::size_t cols, const std::string& where) {
  const hsize_t dims[2] = {rows, cols};
  const hid_t space = H5Screate_simple(cols == 1 ? 1 : 2, dims, nullptr);
  if (space < 0) throw IoError("HDF5: cannot make a dataspace for '" + name + "' in '" + where + "'");
  errno = 0;
  const hid_t set = H5Dcreate2(file, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  herr_t status = -1;
  if (set >= 0) status = (rows * cols == 0) ? 0 : H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  if (set >= 0) H5Dclose(set);
  H5Sclose(space);
  if (set < 0 || status < 0) throw IoError("HDF5: cannot write dataset '" + name + "' to '" + where + "'" + cause());
}

}  // namespace

void Hdf5File::write(const std::string& name, const double* data, std::size_t rows, std::size_t cols) {
  write_dataset(file_, name, H5T_NATIVE_DOUBLE, data, rows, cols, path_);  // named as the user asked
}

void Hdf5File::write(const std::string& name, const std::vector<std::uint64_t>& data) {
  write_dataset(file_, name, H5T_NATIVE_UINT64, data.data(), data.size(), 1, path_);
}

void Hdf5File::attribute(const std::string& name, const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.size() + 1);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(file_, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = attr >= 0 ? H5Awrite(attr, type, value.c_str()) : -1;
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
  if (status < 0) throw IoError("HDF5: cannot write attribute '" + name + "' to '" + path_ + "'");
}

void Hdf5File::commit() {
  errno = 0;
  const herr_t closed = H5Fclose(file_);
  file_ = -1;
  if (closed < 0) throw IoError("HDF5: writing '" + path_ + "' failed" + cause());
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
