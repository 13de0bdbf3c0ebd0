#pragma once
// Plausibility of the numbers a user types: values the physics accepts but that are almost
// always a unit slip — millimetres typed as metres, Hz as kHz, milliseconds as seconds. They earn
// a one-line warning naming the option (the tools print it, Python raises a RuntimeWarning),
// never an error: an unusual study may mean them.
#include <string>
#include <vector>

#include "granular/model/chain_recipe.hpp"

namespace granular {

/// How the caller's user names the recipe's radii: "--R1"/"--types" for the tools, "R1"/"beads"
/// for Python.
struct RadiusNames {
  std::string r1;                         ///< R1 (and ξ R1) of a two-type draw or a types file
  std::string distribution;               ///< the radii of a k-type or polydisperse distribution
  std::string radii;                      ///< a given list of radii (not from a file: files warn per line)
  std::string angle = "angle";            ///< the cylinder chain's α0
  std::string modulation = "modulation";  ///< a quasiperiodic chain's λ
};

/// One warning per recipe radius outside [plausible_radius_min, plausible_radius_max]
/// (bead_distribution.hpp); a given list names its first offender and how many there are. For
/// the cylinder chain also the contact ellipse beyond cylinder_ellipse_warning R
/// (check_cylinder_contacts, quasiperiodic.hpp), which throws InvalidInput where it is refused.
std::vector<std::string> radius_warnings(const ChainRecipe& recipe, const RadiusNames& names);

/// An upper bound [kHz] on every linear frequency of every realization of the recipe:
/// Gershgorin's ω² ≤ 4 B_max / m_min, with B_max the stiffest bond its possible radii can form
/// (the largest bead against a flat wall) and m_min its lightest bead. 0 at F0 = 0.
double highest_frequency_bound_khz(const ChainRecipe& recipe);

/// The warning for a frequency f [kHz] typed as `option` above every frequency of the chain
/// (bound_khz, from highest_frequency_bound_khz); "" when f is below the bound or the bound is 0.
std::string frequency_warning(const std::string& option, double f_khz, double bound_khz);

}  // namespace granular
