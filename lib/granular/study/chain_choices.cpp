#include "granular/study/chain_choices.hpp"

#include "granular/error.hpp"
#include "granular/io/bead_distribution_syntax.hpp"
#include "granular/model/configuration_file.hpp"

namespace granular {

std::optional<Quasiperiodic> quasiperiodic(const ChainChoices& o) {
  if (o.quasi.empty()) return std::nullopt;
  return Quasiperiodic{.kind = parse_quasi_kind(o.quasi),
                       .modulation = o.modulation,
                       .ratio = parse_ratio(o.ratio),
                       .phase = o.phase,
                       .angle = o.angle,
                       .k0 = o.k0,
                       .k0_n_per_m = o.k0_n_per_m};
}

std::optional<BeadDistribution> bead_distribution(const ChainChoices& o) {
  if (!o.types.empty()) return parse_bead_types(o.types, false, parse_disorder(o.disorder), "types");
  if (!o.type_masses.empty()) return parse_bead_types(o.type_masses, true, parse_disorder(o.disorder), "type_masses");
  if (!o.polydisperse.empty()) return parse_polydisperse(o.polydisperse, "polydisperse");
  return std::nullopt;
}

ChainRecipe chain_recipe(const ChainChoices& o, std::vector<std::string>& warnings) {
  if (o.seed < 0) throw InvalidInput("seed", " " + std::to_string(o.seed) + ": must be >= 0");
  if (o.realization < 0) throw InvalidInput("realization", " " + std::to_string(o.realization) + ": must be >= 0");
  if (o.n < 2) throw InvalidInput("N", " " + std::to_string(o.n) + ": a chain needs at least 2 beads");
  ChainRecipe r{.disorder = parse_disorder(o.disorder),
                .q = o.q,
                .xi = o.xi,
                .R1 = o.r1,
                .centred = o.auto_n,
                .N = static_cast<std::size_t>(o.n),
                .F0 = o.f0,
                .seed = static_cast<std::uint64_t>(o.seed)};
  r.walls = parse_wall_shape(o.walls);
  r.distribution = bead_distribution(o);
  if (!o.config.empty()) r.given_types = read_configuration_file(r.source = o.config);
  if (!o.radii.empty()) r.given_radii = read_radii_file(r.source = o.radii, &warnings);
  r.quasi = quasiperiodic(o);
  return r;
}

}  // namespace granular
