#include "granular/crystal/crystal_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "granular/crystal/detail/contact_kinematics.hpp"
#include "granular/error.hpp"

namespace granular {

CrystalMatrix crystal_matrix(const Packing& p, const StaticState& s, const CrystalMatrixConfig& config) {
  if (s.ux.size() != p.size() || s.force.size() != p.contacts.size() ||
      s.wall_stiffness.size() != p.wall_contacts.size())
    throw InvalidInput("state", ": does not belong to this packing (its bead or contact counts differ)");
  const std::size_t beads = p.size();
  CrystalMatrix d;
  d.inverse_sqrt_mass.resize(beads);
  for (std::size_t b = 0; b < beads; ++b) d.inverse_sqrt_mass[b] = 1 / std::sqrt(p.mass[b]);

  // Triplets (row, column, value) of K, scaled by m^{-1/2} on both sides as they are made.
  std::vector<std::size_t> rows, columns;
  std::vector<double> values;
  const std::size_t entries = 16 * p.contacts.size() + 4 * p.wall_contacts.size();
  rows.reserve(entries), columns.reserve(entries), values.reserve(entries);
  auto add_block = [&](std::size_t a, std::size_t b, const detail::Block2& k, double sign) {
    const double w = sign * d.inverse_sqrt_mass[a] * d.inverse_sqrt_mass[b];
    const std::size_t r = 2 * a, c = 2 * b;
    for (const auto& [dr, dc, v] : {std::tuple{0, 0, k.xx}, {0, 1, k.xy}, {1, 0, k.xy}, {1, 1, k.yy}}) {
      rows.push_back(r + static_cast<std::size_t>(dr)), columns.push_back(c + static_cast<std::size_t>(dc));
      values.push_back(w * v);
    }
  };
  for (std::size_t k = 0; k < p.contacts.size(); ++k) {
    const BeadContact& c = p.contacts[k];
    const auto K = detail::contact_block(s.stiffness[k], s.force[k], s.distance[k], s.nx[k], s.ny[k], config.prestress);
    add_block(c.i, c.i, K, 1), add_block(c.j, c.j, K, 1), add_block(c.i, c.j, K, -1), add_block(c.j, c.i, K, -1);
  }
  for (std::size_t k = 0; k < p.wall_contacts.size(); ++k) {
    const auto nw = detail::wall_normal(p.wall_contacts[k].wall);
    const double kn = s.wall_stiffness[k];
    add_block(p.wall_contacts[k].bead, p.wall_contacts[k].bead,
              {kn * nw[0] * nw[0], kn * nw[0] * nw[1], kn * nw[1] * nw[1]}, 1);
  }
  // Summed in ascending order at each position: D(r, c) and D(c, r) add the same numbers in the
  // same order, so the matrix is symmetric to the bit.
  d.matrix = sparse_from_triplets(2 * beads, rows, columns, values);
  return d;
}

std::vector<double> dense(const CrystalMatrix& d) {
  std::vector<double> a(d.rows() * d.rows(), 0.0);
  for (std::size_t r = 0; r < d.rows(); ++r)
    for (auto k = d.matrix.row_start[r]; k < d.matrix.row_start[r + 1]; ++k)
      a[r * d.rows() + static_cast<std::size_t>(d.matrix.column[static_cast<std::size_t>(k)])] =
          d.matrix.value[static_cast<std::size_t>(k)];
  return a;
}

}  // namespace granular
