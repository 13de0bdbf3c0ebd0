#pragma once
// Large numeric arrays in HDF5 (the C API), written atomically like every other output.
#include <cstddef>
#include <string>
#include <vector>

namespace granular {

struct Hdf5Array {
  std::string name;                ///< dataset name at the file's root
  std::vector<std::size_t> shape;  ///< row-major dimensions
  const double* data = nullptr;    ///< product(shape) values
};

/// Writes the arrays as double datasets into a new file, via a temporary name renamed onto
/// `path`. Throws IoError on any HDF5 failure, leaving nothing behind.
void write_hdf5_atomically(const std::string& path, const std::vector<Hdf5Array>& arrays);

}  // namespace granular
