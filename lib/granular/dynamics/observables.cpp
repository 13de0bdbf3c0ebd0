#include "granular/dynamics/observables.hpp"

#include <algorithm>
#include <variant>
#include <vector>

#include "granular/detail/enum_names.hpp"
#include "granular/error.hpp"

namespace granular {

void site_energies(const ForceLaw& law, const Chain& chain, std::span<const double> u, std::span<const double> v,
                   std::span<double> energy, std::size_t begin, std::size_t end) {
  const std::size_t n = u.size();
  end = std::min(end, n);
  std::fill(energy.begin(), energy.end(), 0.0);
  if (begin >= end) return;
  // The bonds' energies first, then the beads': two loops the compiler vectorizes (one loop
  // carrying the right bond's energy to the next bead stays scalar). Scratch per thread.
  thread_local std::vector<double> bond;
  bond.resize(end - begin + 1);
  std::visit(
      [&](const auto& l) {
        // Bonds begin … end: bond begin and bond end may reach one bead outside, at rest. The
        // wall bonds (0 and n) read a wall's zero; every other bond u[k − 1] − u[k].
        double* __restrict phi = bond.data();
        const double* __restrict up = u.data();
        const std::size_t inner_begin = std::max<std::size_t>(begin, 1), inner_end = std::min(end, n - 1);
        for (std::size_t k = begin; k < inner_begin; ++k) phi[k - begin] = l.potential(k, bond_strain(u, k));
        for (std::size_t k = inner_begin; k <= inner_end; ++k) phi[k - begin] = l.potential(k, up[k - 1] - up[k]);
        for (std::size_t k = std::max(inner_end + 1, inner_begin); k <= end; ++k)
          phi[k - begin] = l.potential(k, bond_strain(u, k));
        for (std::size_t i = begin; i < end; ++i)
          energy[i] = 0.5 * chain.mass[i] * v[i] * v[i] + 0.5 * (phi[i - begin] + phi[i + 1 - begin]) +
                      l.onsite_potential(i, u[i]);
        // Half of an edge bond's energy belongs to the (resting) bead just outside the range.
        if (begin > 0) energy[begin - 1] += 0.5 * l.potential(begin, bond_strain(u, begin));
        if (end < n) energy[end] += 0.5 * l.potential(end, bond_strain(u, end));
      },
      law);
}

std::vector<double> site_energies(const ForceLaw& law, const Chain& chain, const State& state) {
  std::vector<double> e(state.size());
  site_energies(law, chain, state.u, state.v, e);
  return e;
}

double total_energy(const ForceLaw& law, const Chain& chain, const State& state) {
  double h = 0;
  for (double e : site_energies(law, chain, state)) h += e;
  return h + unowned_wall_energy(law, state.u);
}

double unowned_wall_energy(const ForceLaw& law, std::span<const double> u) {
  const std::size_t n = u.size();
  return std::visit(
      [&](const auto& l) { return 0.5 * (l.potential(0, bond_strain(u, 0)) + l.potential(n, bond_strain(u, n))); }, law);
}

constexpr auto spread_centre_names =
    detail::enum_names<SpreadCentre>("centre", {{SpreadCentre::site, "site"}, {SpreadCentre::centroid, "centroid"}});

SpreadCentre parse_spread_centre(const std::string& name) { return spread_centre_names.parse(name); }

std::string to_string(SpreadCentre centre) { return std::string(spread_centre_names.name_of(centre)); }

EnergySpread energy_spread(std::span<const double> energy, std::size_t site, std::size_t begin, std::size_t end) {
  end = std::min(end, energy.size());
  begin = std::min(begin, end);
  EnergySpread s;
  double weighted = 0, squares = 0;
  for (std::size_t i = begin; i < end; ++i) {
    s.total += energy[i];
    weighted += static_cast<double>(i) * energy[i];
    squares += energy[i] * energy[i];
  }
  if (!(s.total > 0)) return s;
  s.centroid = weighted / s.total;
  // Both moments summed directly (not one from the other through the identity), so that the
  // identity m2_site = m2_centroid + (n̄ − n0)² is a test of the code, not of algebra.
  const double n0 = static_cast<double>(site);
  double about_centroid = 0, about_site = 0;
  for (std::size_t i = begin; i < end; ++i) {
    const double n = static_cast<double>(i);
    about_centroid += (n - s.centroid) * (n - s.centroid) * energy[i];
    about_site += (n - n0) * (n - n0) * energy[i];
  }
  s.m2_centroid = about_centroid / s.total;
  s.m2_site = about_site / s.total;
  s.ipr = squares / (s.total * s.total);
  return s;
}

void particle_forces(const ForceLaw& law, std::span<const double> u, std::span<double> force) {
  std::visit(
      [&](const auto& l) {
        double left = l.contact_force(0, bond_strain(u, 0));
        for (std::size_t i = 0; i < u.size(); ++i) {
          const double right = l.contact_force(i + 1, bond_strain(u, i + 1));
          force[i] = 0.5 * (left + right);
          left = right;
        }
      },
      law);
}

std::vector<double> particle_forces(const ForceLaw& law, const State& state) {
  std::vector<double> f(state.size());
  particle_forces(law, state.u, f);
  return f;
}

}  // namespace granular
