#pragma once
// The entry point of the HDF5 component (libgranular_hdf5.so, or built into a static
// libgranular): Hdf5File in libgranular writes through it, so only runs that write HDF5 load
// libhdf5 (detail/component.hpp). A file is an HDF5 identifier (hid_t) held as long long.
#include <cstddef>
#include <cstdint>
#include <string>

namespace granular::detail {

/// What the component provides; a table, so that one symbol is looked up. Every function but
/// discard throws IoError naming `shown` (the path the user asked for, or the temporary file's).
struct Hdf5Component {
  /// Creates (truncates) the HDF5 file at `open` (a /proc/self/fd path).
  long long (*create)(const std::string& open, const std::string& shown);
  /// A rows × cols row-major dataset of doubles (cols = 1: 1-D of `rows`).
  void (*write_doubles)(long long file, const std::string& name, const double* data, std::size_t rows, std::size_t cols,
                        const std::string& shown);
  /// A 1-D dataset of n unsigned 64-bit integers.
  void (*write_uint64)(long long file, const std::string& name, const std::uint64_t* data, std::size_t n,
                       const std::string& shown);
  /// A string attribute on the root group.
  void (*attribute)(long long file, const std::string& name, const std::string& value, const std::string& shown);
  /// Closes the file, flushing it.
  void (*close)(long long file, const std::string& shown);
  /// Closes the file without reporting (an output abandoned on an error path).
  void (*discard)(long long file);
};

/// The component's table, loaded on first use.
const Hdf5Component& hdf5_component();

}  // namespace granular::detail

/// The component's table (C linkage: the name dlsym looks up).
extern "C" const granular::detail::Hdf5Component* granular_hdf5_component();
