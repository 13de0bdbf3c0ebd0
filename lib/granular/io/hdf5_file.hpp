#pragma once
// An HDF5 file of named 1-D and 2-D double / integer arrays that appears whole or not at all:
// written under a temporary name, fsynced and renamed on commit() (as AtomicFile is).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "granular/io/pending_output.hpp"

namespace granular {

namespace detail {
class TemporaryFile;
}

class Hdf5File : public PendingOutput {
 public:
  /// Creates PATH.tmp.<pid>; throws IoError.
  explicit Hdf5File(std::string path);
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;
  ~Hdf5File() override;

  /// A rows × cols row-major dataset (cols = 1 writes a 1-D dataset of `rows`).
  void write(const std::string& name, const double* data, std::size_t rows, std::size_t cols = 1);
  void write(const std::string& name, const std::vector<double>& data) { write(name, data.data(), data.size()); }
  void write(const std::string& name, const std::vector<std::uint64_t>& data);
  /// A string attribute on the root group.
  void attribute(const std::string& name, const std::string& value);
  /// Closes, fsyncs and renames onto the target, then fsyncs the folder; throws IoError.
  void commit() override;

 private:
  std::string path_;
  std::unique_ptr<detail::TemporaryFile> temporary_;  // PATH.tmp.<pid>, removed unless committed
  long long file_ = -1;                               // hid_t
};

/// Loads the HDF5 writer's component now; throws IoError when it is missing or does not load. A
/// run that will write HDF5 calls it while checking its options, so that a missing component
/// fails before the work rather than after it (the component loads once; later calls are free).
void load_hdf5_writer();

/// A named array for write_hdf5_atomically: 1-D or 2-D (row-major) doubles.
struct Hdf5Array {
  std::string name;                ///< dataset name at the file's root
  std::vector<std::size_t> shape;  ///< {n} or {rows, cols}
  const double* data = nullptr;    ///< product(shape) values
};

/// Writes the arrays into a new file that appears whole or not at all; throws IoError.
void write_hdf5_atomically(const std::string& path, const std::vector<Hdf5Array>& arrays);

}  // namespace granular
