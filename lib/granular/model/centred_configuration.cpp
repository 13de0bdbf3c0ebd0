#include "granular/model/centred_configuration.hpp"

#include <algorithm>

namespace granular {

Configuration centred_configuration(Disorder disorder, double q, std::size_t n, std::uint64_t seed,
                                    std::uint64_t realization) {
  const std::size_t unit = disorder == Disorder::rdm1 || disorder == Disorder::rdm2 ? 2 : 1;
  const std::size_t centre = n == 0 ? 0 : (n - 1) / 2;
  const std::size_t right_units = (n - centre + unit - 1) / unit, left_units = (centre + unit - 1) / unit;
  const std::size_t units = 2 * std::max(right_units, left_units);
  // The usual draw uses the i-th uniform for unit i (disorder.hpp), so this prefix is the same
  // for every N that needs at least these units.
  const Configuration drawn = realization_configuration(disorder, q, units * unit, seed, realization);
  Configuration types(n, 1);
  for (std::size_t j = 0; j < right_units; ++j)
    for (std::size_t b = 0; b < unit && centre + j * unit + b < n; ++b)
      types[centre + j * unit + b] = drawn[2 * j * unit + b];
  for (std::size_t j = 0; j < left_units; ++j)
    for (std::size_t b = 0; b < unit; ++b) {
      const std::size_t offset = (j + 1) * unit - b;  // bead c − offset holds bead b of the unit
      if (offset <= centre) types[centre - offset] = drawn[(2 * j + 1) * unit + b];
    }
  return types;
}

}  // namespace granular
