#include "granular/model/named_chains.hpp"

#include <cmath>
#include <string>

#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {

void validate(const ChainParameters& p) {
  if (p.N < 2) throw InvalidInput("N", " " + std::to_string(p.N) + ": a chain needs at least 2 beads");
  if (p.N > 100000000) throw InvalidInput("N", " " + std::to_string(p.N) + ": more than 1e8 beads");
  validate_probability(p.q);
  validate_size_ratio(p.xi);
  if (!std::isfinite(p.F0) || p.F0 < 0)
    throw InvalidInput("F0", " " + format_number(p.F0) + ": must be finite and >= 0");
  if (!std::isfinite(p.R1) || p.R1 <= 0)
    throw InvalidInput("R1", " " + format_number(p.R1) + ": must be finite and > 0");
  validate(p.material, "material");
}

Chain random_chain(Disorder disorder, const ChainParameters& p) {
  validate(p);
  return from_types(realization_configuration(disorder, p.q, p.N, p.seed, p.realization), p);
}

Chain diatomic(const ChainParameters& p) {
  validate(p);
  Configuration types(p.N);
  for (std::size_t i = 0; i < p.N; ++i) types[i] = i % 2 == 0 ? 1 : 2;
  return from_types(types, p);
}

Chain from_types(const Configuration& types, const ChainParameters& p) {
  validate_size_ratio(p.xi);
  if (!std::isfinite(p.R1) || p.R1 <= 0)
    throw InvalidInput("R1", " " + format_number(p.R1) + ": must be finite and > 0");
  for (std::size_t i = 0; i < types.size(); ++i)
    if (types[i] != 1 && types[i] != 2)
      throw InvalidInput("types", ": bead " + std::to_string(i + 1) + " has type " + std::to_string(types[i]) +
                                      " (must be 1 or 2)");
  return make_chain(radii_of(types, p.R1, p.xi), p.F0, p.material);
}

Chain from_radii(const std::vector<double>& radii, double F0, const Material& material) {
  return make_chain(radii, F0, material);
}

}  // namespace granular
