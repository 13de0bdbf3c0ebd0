#pragma once
// Shared by the breather tests: how far a computed breather is from periodic under direct integration;
// the verdict flags of a branch's HDF5 file.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include <hdf5.h>

#include "granular/dynamics/propagator.hpp"
#include "granular/orbits/breather_branch.hpp"

namespace granular::fixtures {

/// ‖(u − x0, u̇/ω_b)‖/‖x0‖ after `periods` periods of direct integration (SABA2C, `steps` per
/// period) from the breather's turning state (x0, 0).
inline double state_error_after(const Chain& chain, const BreatherPoint& p, std::size_t steps, std::size_t periods) {
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  State start(chain.size());
  start.u = p.x0;
  const double tau = 2 * std::numbers::pi / p.omega / static_cast<double>(steps);
  auto prop = make_splitting_propagator(law, chain, saba2c(), tau, start, {.enabled = false});
  prop->advance(periods * steps);
  double err = 0, norm = 0;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    err += std::pow(prop->displacement()[i] - p.x0[i], 2) + std::pow(prop->velocity()[i] / p.omega, 2);
    norm += p.x0[i] * p.x0[i];
  }
  return std::sqrt(err / norm);
}

/// What a breather branch's HDF5 file (write_breather_hdf5) says of its verdicts: the dataset
/// verdict_trusted (one value per point, read as written: 64-bit unsigned) and the root attribute
/// verdict_untrusted_reason. `ok` is false when the file, the dataset or the attribute is missing.
struct Hdf5Verdicts {
  bool ok = false;
  std::vector<std::uint64_t> trusted;
  std::string reason;
};

inline Hdf5Verdicts read_hdf5_verdicts(const std::string& path) {
  Hdf5Verdicts out;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return out;
  const hid_t set = H5Dopen2(file, "verdict_trusted", H5P_DEFAULT);
  const hid_t attribute = H5Aopen(file, "verdict_untrusted_reason", H5P_DEFAULT);
  if (set >= 0 && attribute >= 0) {
    const hid_t space = H5Dget_space(set);
    const hid_t stored = H5Dget_type(set);
    const hid_t text = H5Aget_type(attribute);
    hsize_t rows = 0;
    const bool one_dimension =
        H5Sget_simple_extent_ndims(space) == 1 && H5Sget_simple_extent_dims(space, &rows, nullptr) == 1;
    const bool unsigned_64 =
        H5Tget_class(stored) == H5T_INTEGER && H5Tget_size(stored) == 8 && H5Tget_sign(stored) == H5T_SGN_NONE;
    out.trusted.resize(rows);
    std::string reason(H5Tget_size(text), '\0');
    out.ok = one_dimension && unsigned_64 && H5Tget_class(text) == H5T_STRING &&
             (rows == 0 || H5Dread(set, H5T_NATIVE_UINT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.trusted.data()) >= 0) &&
             H5Aread(attribute, text, reason.data()) >= 0;
    out.reason = reason.c_str();  // up to the terminating NUL the writer stores
    H5Tclose(text);
    H5Tclose(stored);
    H5Sclose(space);
  }
  if (attribute >= 0) H5Aclose(attribute);
  if (set >= 0) H5Dclose(set);
  H5Fclose(file);
  return out;
}

}  // namespace granular::fixtures
