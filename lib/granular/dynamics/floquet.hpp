#pragma once
// Floquet stability of a periodic orbit (docs/breathers.md): the monodromy matrix, the tangent map
// of one full period T of the same scheme that found the orbit (periodic_orbit.hpp), and its
// eigenvalues, the Floquet multipliers μ. A perturbation grows like |μ|^{t/T}: the orbit is
// linearly stable when every |μ| ≤ 1 + tolerance (the +1 pair aside). The map is symplectic, so the multipliers come
// in reciprocal pairs (μ, 1/μ) and complex-conjugate pairs (μ, μ̄), their product is 1, and
// the time shift along the orbit and the change along the family give a pair at +1. Those are
// what the *_error fields measure: a multiplier off the unit circle in a symplectic spectrum means
// instability, never decay.
//
// Coordinates (δu, δv/ω_b), both in metres: the multipliers do not depend on the scaling, the
// conditioning of dgeev does.
#include <complex>
#include <cstddef>
#include <string>
#include <vector>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/periodic_orbit.hpp"

namespace granular {

/// The 2N × 2N monodromy matrix of `orbit` (column-major, coordinates (δu, δv/ω_b)): 2N tangent
/// integrations of one period.
std::vector<double> monodromy_matrix(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit);

struct FloquetSpectrum {
  std::vector<std::complex<double>> multipliers;  ///< the 2N eigenvalues of the monodromy matrix, by |μ| descending
  /// max |μ| over all but the two multipliers nearest +1 (the phase/family pair, a Jordan block
  /// that a residual r of the orbit splits by ~√r: not an instability)
  double max_modulus = 0;
  bool stable = false;   ///< max_modulus ≤ 1 + tolerance
  double tolerance = 0;  ///< of `stable`
  /// "none", "real" (a real multiplier > 1: exponential instability) or "oscillatory" (a complex
  /// quartet off the circle).
  std::string instability = "none";
  double growth_rate = 0;  ///< ln(max_modulus)/T [1/s]: how fast the worst perturbation grows
  /// Symplectic checks: max over μ of min_ν |ν − 1/μ| (reciprocal pairs) and of min_ν |ν − μ̄|
  /// (conjugate pairs), relative to max(1, |μ|); |Π μ − 1|; and the distance of the two multipliers
  /// nearest +1 from it (a Jordan block there: it splits by ~√ε, not ε).
  double reciprocal_error = 0;
  double conjugate_error = 0;
  double product_error = 0;
  double unit_pair_distance = 0;
};

/// The multipliers of a monodromy matrix of `beads` beads (2N × 2N, consumed), the orbit's period
/// T [s] for the growth rate. Throws NumericalError if dgeev fails.
FloquetSpectrum floquet_spectrum(std::vector<double> monodromy, std::size_t beads, double period,
                                 double tolerance = 1e-6);

/// monodromy_matrix then floquet_spectrum.
FloquetSpectrum floquet_stability(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit,
                                  double tolerance = 1e-6);

}  // namespace granular
