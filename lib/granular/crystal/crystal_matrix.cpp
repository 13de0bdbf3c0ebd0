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
  d.rows = 2 * beads;
  d.inverse_sqrt_mass.resize(beads);
  for (std::size_t b = 0; b < beads; ++b) d.inverse_sqrt_mass[b] = 1 / std::sqrt(p.mass[b]);

  // Triplets (row, column, value) of K, scaled by m^{-1/2} on both sides as they are made.
  std::vector<std::tuple<std::int64_t, std::int64_t, double>> t;
  t.reserve(16 * p.contacts.size() + 4 * p.wall_contacts.size());
  auto add_block = [&](std::size_t a, std::size_t b, const detail::Block2& k, double sign) {
    const double w = sign * d.inverse_sqrt_mass[a] * d.inverse_sqrt_mass[b];
    const auto r = static_cast<std::int64_t>(2 * a), c = static_cast<std::int64_t>(2 * b);
    t.emplace_back(r, c, w * k.xx), t.emplace_back(r, c + 1, w * k.xy);
    t.emplace_back(r + 1, c, w * k.xy), t.emplace_back(r + 1, c + 1, w * k.yy);
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
  // Sorting fixes the order in which duplicates are summed, so D(r, c) and D(c, r) add the same
  // numbers in the same order and the matrix is symmetric to the bit.
  std::sort(t.begin(), t.end());
  d.row_start.assign(d.rows + 1, 0);
  for (std::size_t n = 0; n < t.size();) {
    const auto [r, c, v0] = t[n];
    double v = v0;
    for (++n; n < t.size() && std::get<0>(t[n]) == r && std::get<1>(t[n]) == c; ++n) v += std::get<2>(t[n]);
    d.column.push_back(c), d.value.push_back(v);
    ++d.row_start[static_cast<std::size_t>(r) + 1];
  }
  for (std::size_t r = 0; r < d.rows; ++r) d.row_start[r + 1] += d.row_start[r];
  return d;
}

std::vector<double> dense(const CrystalMatrix& d) {
  std::vector<double> a(d.rows * d.rows, 0.0);
  for (std::size_t r = 0; r < d.rows; ++r)
    for (auto k = d.row_start[r]; k < d.row_start[r + 1]; ++k)
      a[r * d.rows + static_cast<std::size_t>(d.column[static_cast<std::size_t>(k)])] =
          d.value[static_cast<std::size_t>(k)];
  return a;
}

}  // namespace granular
