#pragma once
// Symmetric drift–kick splitting schemes as data (docs/physics.md, "Nonlinear dynamics"). A step of length τ is
//   [corrector g τ³]  D(a_0 τ) K(b_0 τ) D(a_1 τ) … K(b_{s−1} τ) D(a_s τ)  [corrector g τ³]
// with D a drift (u += h v) and K a kick (v += h F/m). The corrector, when g ≠ 0, is the
// momentum kick of the flow of {{A,B},B} (SABA2C). One stepper runs every scheme.
#include <string>
#include <string_view>
#include <vector>

namespace granular {

struct SplittingScheme {
  std::string name;
  std::vector<double> drift;  ///< a_0 … a_s (s+1 entries), sum 1
  std::vector<double> kick;   ///< b_0 … b_{s−1} (s entries), sum 1
  double corrector = 0;       ///< g; 0 for none
  int order = 2;              ///< the global order of accuracy on smooth problems

  std::size_t force_evaluations_per_step() const { return kick.size() + (corrector != 0 ? 1 : 0); }
};

/// SABA2 with Laskar–Robutel's corrector, 4th order: c1 = 1/2 − √3/6, c2 = √3/3, d1 = 1/2,
/// g = (2 − √3)/24.
SplittingScheme saba2c();
/// The same without corrector (2nd order); what the order test compares against.
SplittingScheme saba2();
/// Blanes et al. (2013) ABA864: 4th order, 7 kicks.
SplittingScheme aba864();
/// Blanes & Moan (2002) SRKN14a: 6th order, 14 kicks.
SplittingScheme srkn14a();

/// saba2c | saba2 | aba864 | srkn14a (any case); throws InvalidInput naming `parameter`.
SplittingScheme parse_scheme(std::string_view name, const std::string& parameter = "scheme");

}  // namespace granular
