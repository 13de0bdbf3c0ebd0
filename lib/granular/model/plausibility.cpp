#include "granular/model/plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "granular/model/configuration_file.hpp"
#include "granular/model/contact_law.hpp"
#include "granular/model/quasiperiodic.hpp"
#include "granular/number_format.hpp"

namespace granular {

std::vector<std::string> radius_warnings(const ChainRecipe& recipe, const RadiusNames& names) {
  std::vector<std::string> out;
  if (const auto* given = recipe.as<GivenRadii>()) {
    if (!given->file.empty()) return out;  // read_radii_file warned, naming the line
    const auto& radii = given->radii;
    const auto bad = std::count_if(radii.begin(), radii.end(), [](double r) { return !plausible_radius(r); });
    if (bad == 0) return out;
    const auto first = std::find_if(radii.begin(), radii.end(), [](double r) { return !plausible_radius(r); });
    std::string where = names.radii + "[" + std::to_string(first - radii.begin()) + "]";
    std::string w = implausible_radius_warning(where, *first);
    if (bad > 1) w += " (and " + std::to_string(bad - 1) + " more)";
    out.push_back(std::move(w));
    return out;
  }
  if (const auto* d = recipe.as<BeadDistribution>()) {  // the radii the user typed, not the tail of a normal
    std::vector<double> typed = d->radii;
    if (d->kind == BeadDistribution::Kind::uniform) typed = {d->low, d->high};
    if (d->kind == BeadDistribution::Kind::normal) typed = {d->mean, d->minimum};
    for (double r : typed)
      if (!plausible_radius(r)) out.push_back(implausible_radius_warning(names.distribution, r));
    return out;
  }
  if (!plausible_radius(recipe.R1)) out.push_back(implausible_radius_warning(names.r1, recipe.R1));
  else if (recipe.typed() && !plausible_radius(recipe.xi() * recipe.R1))
    out.push_back(implausible_radius_warning(names.r1 + " times xi", recipe.xi() * recipe.R1));
  if (const auto* quasi = recipe.as<Quasiperiodic>())
    if (std::string w =
            check_cylinder_contacts(*quasi, recipe.R1, recipe.F0, recipe.material, names.angle, names.modulation);
        !w.empty())
      out.push_back(std::move(w));
  return out;
}

double highest_frequency_bound_khz(const ChainRecipe& recipe) {
  if (const auto* quasi = recipe.as<Quasiperiodic>(); quasi && recipe.F0 > 0)
    return quasiperiodic_omega_bound(*quasi, recipe.R1, recipe.F0, recipe.material) / (2 * std::numbers::pi) / 1000;
  const std::vector<double> radii = recipe.possible_radii();
  if (radii.empty() || !(recipe.F0 > 0)) return 0;
  const auto [smallest, largest] = std::minmax_element(radii.begin(), radii.end());
  const double stiffest =
      linear_stiffness(hertz_coefficient(recipe.material, *largest, recipe.material, flat_wall), recipe.F0);
  const double omega = std::sqrt(4 * stiffest / sphere_mass(recipe.material, *smallest));
  return omega / (2 * std::numbers::pi) / 1000;
}

std::string frequency_warning(const std::string& option, double f_khz, double bound_khz) {
  if (!(bound_khz > 0) || !(f_khz > bound_khz)) return "";
  return option + " " + format_number(f_khz) + ": above every frequency of this chain (all below " +
         format_number(std::ceil(bound_khz)) + " kHz); frequencies are in kHz (Hz typed as kHz?)";
}

}  // namespace granular
