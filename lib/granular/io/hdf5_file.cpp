#include "granular/io/hdf5_file.hpp"

#include <cstdio>
#include <filesystem>

#include <hdf5.h>

#include "granular/error.hpp"

namespace granular {

void write_hdf5_atomically(const std::string& path, const std::vector<Hdf5Array>& arrays) {
  const std::string temporary = path + ".tmp";
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not stderr noise
  const hid_t file = H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0) throw IoError("cannot create HDF5 file " + temporary);
  bool ok = true;
  for (const Hdf5Array& a : arrays) {
    std::vector<hsize_t> dims(a.shape.begin(), a.shape.end());
    const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
    const hid_t set = space < 0 ? -1
                                : H5Dcreate2(file, a.name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT,
                                             H5P_DEFAULT);
    ok = ok && set >= 0 && H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.data) >= 0;
    if (set >= 0) H5Dclose(set);
    if (space >= 0) H5Sclose(space);
  }
  ok = H5Fclose(file) >= 0 && ok;
  std::error_code ec;
  if (ok) std::filesystem::rename(temporary, path, ec);
  if (!ok || ec) {
    std::filesystem::remove(temporary, ec);
    throw IoError("writing HDF5 file " + path + " failed");
  }
}

}  // namespace granular
