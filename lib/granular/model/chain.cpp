#include "granular/model/chain.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {

Chain make_chain(const ChainSpec& spec) {
  const std::size_t n = spec.radii.size();
  if (n < 2) throw InvalidInput("N", " " + std::to_string(n) + ": a chain needs at least 2 beads");
  if (spec.materials.size() != 1 && spec.materials.size() != n)
    throw InvalidInput("materials", ": give one material or one per bead (" + std::to_string(n) + ")");
  if (!std::isfinite(spec.precompression) || spec.precompression < 0)
    throw InvalidInput("F0", " " + format_number(spec.precompression) + ": must be finite and >= 0");
  for (const Material& m : spec.materials) validate(m, "bead material");
  validate(spec.left_wall.material, "left wall");
  validate(spec.right_wall.material, "right wall");
  for (const Wall* w : {&spec.left_wall, &spec.right_wall})
    if (!(w->radius > 0)) throw InvalidInput("wall_radius", ": must be > 0 (or infinite for a flat wall)");

  auto material_of = [&](std::size_t i) -> const Material& {
    return spec.materials.size() == 1 ? spec.materials[0] : spec.materials[i];
  };
  Chain c;
  c.precompression = spec.precompression;
  c.radius = spec.radii;
  c.mass.resize(n);
  c.inverse_mass.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = spec.radii[i];
    if (!std::isfinite(r) || r <= 0)
      throw InvalidInput("radii", ": bead " + std::to_string(i + 1) + " has radius " + format_number(r) +
                                      " m (must be finite and > 0)");
    c.mass[i] = sphere_mass(material_of(i), r);
    c.inverse_mass[i] = 1.0 / c.mass[i];
  }
  const Material& left = spec.walls_match_beads ? material_of(0) : spec.left_wall.material;
  const Material& right = spec.walls_match_beads ? material_of(n - 1) : spec.right_wall.material;
  c.contact.resize(n + 1);
  c.contact[0] = hertz_coefficient(left, spec.left_wall.radius, material_of(0), spec.radii[0]);
  for (std::size_t k = 1; k < n; ++k)
    c.contact[k] = hertz_coefficient(material_of(k - 1), spec.radii[k - 1], material_of(k), spec.radii[k]);
  c.contact[n] = hertz_coefficient(material_of(n - 1), spec.radii[n - 1], right, spec.right_wall.radius);
  c.overlap.resize(n + 1);
  for (std::size_t k = 0; k <= n; ++k) c.overlap[k] = static_overlap(c.contact[k], spec.precompression);
  return c;
}

std::vector<double> linear_stiffness(const Chain& chain) {
  if (!chain.spring.empty()) return chain.spring;
  std::vector<double> b(chain.bonds());
  for (std::size_t k = 0; k < b.size(); ++k) b[k] = linear_stiffness(chain.contact[k], chain.precompression);
  return b;
}

Chain make_chain(const std::vector<double>& radii, double precompression, const Material& material) {
  ChainSpec spec;
  spec.radii = radii;
  spec.materials = {material};
  spec.precompression = precompression;
  return make_chain(spec);
}

}  // namespace granular
