#pragma once
// Quasiperiodic granular chains (docs/physics.md, "Quasiperiodic chains"), after Martínez, Porter
// & Kevrekidis, Phil. Trans. R. Soc. A 376, 20170139 (2018): a modulation cos(2πβn + φ) of
// incommensurate ratio β and phase φ on the beads (S1: on-site springs, S2: masses) or on the
// bonds (C: the crossing angles of cylinders). The phase plays the role of the realization:
// realization r of seed s draws φ uniformly in [0, 2π) from the Philox stream of (s, r)
// (random_stream.hpp), unless a phase is given.
//
//   granular::ChainRecipe recipe{.N = 987, .seed = 3};
//   recipe.source = granular::Quasiperiodic{.kind = granular::Quasiperiodic::Kind::s2, .modulation = 0.5};
//   granular::Chain chain = recipe.chain(r);  // φ of realization r
//
// Beads count n = 1 … N and bonds k = 0 … N (bond k joins beads k and k+1; 0 and N are the walls).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/model/chain.hpp"
#include "granular/model/material.hpp"

namespace granular {

/// The golden mean (√5 − 1)/2, the default incommensurate ratio.
inline constexpr double golden_mean = 0.6180339887498948482;

struct Quasiperiodic {
  enum class Kind {
    s1,         ///< spheres on on-site springs k_n = k0 [1 + λ cos(2πβn + φ)]
    s2,         ///< spheres of one radius, masses m_n = m [1 + λ cos(2πβn + φ)]
    cylinders,  ///< identical cylinders, crossing angles α_k = α0 [1 + λ cos(2πβk + φ)]
  };
  Kind kind = Kind::s2;
  double modulation = 0;          ///< λ, the relative modulation strength; |λ| < 1 (S2, C), k_n > 0 (S1)
  double ratio = golden_mean;     ///< β > 0, finite
  std::optional<double> phase{};  ///< φ [rad]; none: drawn per realization
  double angle = 45;              ///< C: α0 [degrees] in (0, 180); α_k must stay in (0, 180)
  double k0 = 4;                  ///< S1: k0 in units of the bond stiffness K (the transition at λ k0 = 2K)
  /// S1: k0 [N/m] in absolute units instead (0: use k0 × K). The only way to give S1 at F0 = 0,
  /// where K = 0: beads on springs touching without precompression (a Newton's cradle).
  double k0_n_per_m = 0;
};

/// The cylinders' length: twice their radius (L = 2R, mass ρ π R² L).
inline constexpr double cylinder_length_over_radius = 2;

/// C: the point-contact (Hertz) law describes two crossed cylinders while their contact ellipse is
/// small against them, its major semi-axis a ≪ R (the ellipse lies along the axes as they turn
/// parallel, and the cylinders' half-length is R). At the static overlap under F0, at the angle of
/// any phase where a is largest: a > cylinder_ellipse_warning R earns a warning (a ≪ R no longer
/// holds: 10 degrees at the paper's beads and F0 = 10 N), a ≥ cylinder_ellipse_limit R is refused
/// (the ellipse spans half the cylinders' length: a line contact, not a point; 1 degree there).
/// docs/physics.md, "C — cylinders at quasiperiodic crossing angles".
inline constexpr double cylinder_ellipse_warning = 0.1, cylinder_ellipse_limit = 0.5;

/// C: the largest a/R of a bond at its static overlap under F0 over the angles α0 (1 ± |λ|) any
/// phase gives (a grows as the axes turn parallel, so the largest is at one end), and that angle
/// [degrees]. {0, 0} for S1, S2 or F0 = 0.
struct CylinderContactExtent {
  double semi_axis_over_radius = 0;
  double angle_deg = 0;
};
CylinderContactExtent cylinder_contact_extent(const Quasiperiodic& q, double R, double F0, const Material& material);

/// C: throws InvalidInput naming `angle` (α0 alone already too near parallel) or `modulation`
/// where the extent reaches cylinder_ellipse_limit; "" or the warning's text (naming `angle` or
/// `modulation` as the caller's user calls them) beyond cylinder_ellipse_warning.
std::string check_cylinder_contacts(const Quasiperiodic& q, double R, double F0, const Material& material,
                                    const std::string& angle_name = "angle",
                                    const std::string& modulation_name = "modulation");

/// "s1", "s2", "cylinders".
std::string to_string(Quasiperiodic::Kind kind);
/// Throws InvalidInput ("quasi") naming the accepted words.
Quasiperiodic::Kind parse_quasi_kind(const std::string& word);
/// β from "golden", "p/q" or a number; throws InvalidInput ("ratio").
double parse_ratio(const std::string& text);

/// The phase φ of realization r of seed s: the given one, or 2π times the stream's first uniform.
double quasiperiodic_phase(const Quasiperiodic& q, std::uint64_t seed, std::uint64_t r);

/// The modulation factor 1 + λ cos(2πβn + φ) of site n.
inline double modulation_factor(const Quasiperiodic& q, double phase, std::size_t n) {
  return 1 + q.modulation * std::cos(2 * std::numbers::pi * q.ratio * static_cast<double>(n) + phase);
}

/// Throws InvalidInput naming the field (ratio, modulation, phase, angle, k0, k0_n_per_m; F0 for S1 without k0_n_per_m,
/// which needs F0 > 0 to define K) when a mass, stiffness or angle could leave its range at any phase.
void validate(const Quasiperiodic& q, double F0);

/// Realization of phase φ: N beads of radius R [m] (spheres, or cylinders of length 2R) of one
/// material under precompression F0 [N]; flat walls for spheres, fixed cylinders crossing at
/// angle α_0 and α_N for C (a cylinder on a flat is a line contact, not Hertzian).
Chain quasiperiodic_chain(const Quasiperiodic& q, std::size_t N, double R, double F0, const Material& material,
                          double phase);

/// Three-bead chains holding every extreme neighbourhood any phase can give (the lightest and
/// heaviest masses, the softest and stiffest bonds, each combination): what a worst-case rule
/// over all realizations (the time-step rule) must try.
std::vector<Chain> quasiperiodic_local_chains(const Quasiperiodic& q, double R, double F0, const Material& material);

/// The largest linear frequency [rad/s] any phase can give: Gershgorin's bound with the stiffest
/// bond, the largest on-site spring and the lightest bead.
double quasiperiodic_omega_bound(const Quasiperiodic& q, double R, double F0, const Material& material);

/// kind, modulation, ratio, and phase (given) or phase_rule, angle_deg (C), k0_over_K or k0_N_per_m (S1).
nlohmann::json describe(const Quasiperiodic& q);
/// The inverse of describe; throws InvalidInput naming the key.
Quasiperiodic parse_quasiperiodic(const nlohmann::json& j);

}  // namespace granular
