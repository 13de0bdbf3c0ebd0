// The HDF5 component (libgranular_hdf5.so; hdf5_component.hpp): the only file that calls libhdf5.
#include <cerrno>
#include <cstring>

#include <hdf5.h>

#include "granular/error.hpp"
#include "granular/io/detail/hdf5_component.hpp"

namespace granular {

namespace {

/// HDF5 prints its whole internal error stack on stderr by default; failures here become one
/// IoError naming the file and the system's cause instead.
void silence_hdf5() {
  static const bool silenced = [] { return H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) >= 0; }();
  (void)silenced;
}

/// ": No space left on device" when the C library recorded why; "" otherwise.
std::string hdf5_cause() { return errno ? std::string(": ") + std::strerror(errno) : std::string(); }

long long create_hdf5(const std::string& open, const std::string& shown) {
  silence_hdf5();
  errno = 0;
  const hid_t file = H5Fcreate(open.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0) throw IoError("cannot create HDF5 file '" + shown + "'" + hdf5_cause());
  return file;
}

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
  if (set < 0 || status < 0)
    throw IoError("HDF5: cannot write dataset '" + name + "' to '" + where + "'" + hdf5_cause());
}

void write_doubles(long long file, const std::string& name, const double* data, std::size_t rows, std::size_t cols,
                   const std::string& shown) {
  write_dataset(file, name, H5T_NATIVE_DOUBLE, data, rows, cols, shown);
}

void write_uint64(long long file, const std::string& name, const std::uint64_t* data, std::size_t n,
                  const std::string& shown) {
  write_dataset(file, name, H5T_NATIVE_UINT64, data, n, 1, shown);
}

void write_attribute(long long file, const std::string& name, const std::string& value, const std::string& shown) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.size() + 1);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(file, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = attr >= 0 ? H5Awrite(attr, type, value.c_str()) : -1;
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
  if (status < 0) throw IoError("HDF5: cannot write attribute '" + name + "' to '" + shown + "'");
}

void close_hdf5(long long file, const std::string& shown) {
  errno = 0;
  if (H5Fclose(file) < 0) throw IoError("HDF5: writing '" + shown + "' failed" + hdf5_cause());
}

void discard_hdf5(long long file) { H5Fclose(file); }

}  // namespace

}  // namespace granular

const granular::detail::Hdf5Component* granular_hdf5_component() {
  using namespace granular;
  static const detail::Hdf5Component component{&create_hdf5,     &write_doubles, &write_uint64,
                                               &write_attribute, &close_hdf5,    &discard_hdf5};
  return &component;
}
