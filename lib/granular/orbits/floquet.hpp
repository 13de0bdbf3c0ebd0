#pragma once
// Floquet stability of a periodic orbit (docs/breathers.md): the monodromy matrix, the tangent map
// of one full period T of the same scheme that found the orbit (periodic_orbit.hpp), and its
// eigenvalues, the Floquet multipliers μ. A perturbation grows like |μ|^{t/T}: the orbit is
// linearly stable when every |μ| ≤ 1 + tolerance (the +1 pair aside). The map is symplectic, so the multipliers come
// in reciprocal pairs (μ, 1/μ) with product 1, and the time shift along the orbit and the change
// along the family give a pair at +1: what reciprocal_error and product_error measure. A
// multiplier off the unit circle in a symplectic spectrum means instability, never decay.
//
// The +1 pair, one rule for both methods: of the multipliers within unit_pair_window of +1, the
// two nearest (fewer when fewer lie there) are the phase/family pair, a Jordan block that an orbit
// periodic to a residual r splits by ~√r; they are left out of the verdict. Every other multiplier
// counts, however near +1 (unit_pair).
//
// Coordinates (δu, δv/ω_b), both in metres: the multipliers do not depend on the scaling, the
// conditioning of dgeev does.
//
// Two methods. Dense: the 2N × 2N matrix (2N tangent integrations) and LAPACK dgeev, all 2N
// multipliers. ARPACK (large N): the monodromy only as an operator, v ↦ M v by one tangent
// integration of a period, and the implicitly restarted Arnoldi method (dnaupd/dneupd) for the k
// multipliers of largest modulus, which decide stability (k + 1 when the cut splits a conjugate
// pair: the partner is restored). The reciprocal pairs and the product do not apply to those k
// (the 1/μ are the smallest, not computed) and are NaN; instead each multiplier carries dnaupd's
// Ritz estimate and the residual ‖M z − μ z‖/(|μ| ‖z‖) of its Ritz vector z, measured by one more
// application of M, which must be at most ritz_residual_limit or the set counts as incomplete.
// An incomplete set is never called stable: its verdict is unstable (a converged multiplier grows)
// or unknown.
#include <complex>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "granular/dynamics/force_law.hpp"
#include "granular/orbits/periodic_orbit.hpp"

namespace granular {

/// The 2N × 2N monodromy matrix of `orbit` (column-major, coordinates (δu, δv/ω_b)): 2N tangent
/// integrations of one period.
std::vector<double> monodromy_matrix(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit);

/// dense: the whole matrix and dgeev; arpack: the largest-modulus multipliers from the operator;
/// automatic: dense up to FloquetConfig::max_dense_beads, ARPACK beyond.
enum class FloquetMethod { automatic, dense, arpack };
FloquetMethod parse_floquet_method(const std::string& name);  ///< "auto" | "dense" | "arpack"
std::string to_string(FloquetMethod method);

struct FloquetConfig {
  double tolerance = 1e-6;  ///< stable when every |μ| ≤ 1 + this (the +1 pair aside)
  FloquetMethod method = FloquetMethod::automatic;
  /// automatic: dense up to this N (2N tangent integrations and a 2N × 2N dgeev), ARPACK beyond.
  std::size_t max_dense_beads = 1000;
  /// automatic, up to this N: ARPACK within the dense method's cost (about 2N applications of M,
  /// its restarts capped to fit), then, unless every multiplier converged (stable orbits, where
  /// every |μ| = 1, seldom do), the dense method after all (its 2N × 2N dgeev: ~4 s per point at
  /// N = 1001). Beyond this N, ARPACK alone with max_restarts.
  std::size_t max_fallback_beads = 3000;
  int multipliers = 16;  ///< ARPACK: how many of the largest |μ| (1 … 2N − 3)
  /// ARPACK: Krylov basis size (ncv); 0: max(2 multipliers + 1, 40), at most 2N.
  int subspace = 0;
  double arpack_tolerance = 1e-12;  ///< ARPACK: relative residual of the Ritz pairs
  /// ARPACK: implicit restarts; when they run out, the multipliers converged so far are kept
  /// (FloquetSpectrum::complete = false; none converged: NumericalError).
  int max_restarts = 300;
  /// Both methods: of the multipliers within this distance of +1, the two nearest are the
  /// phase/family pair, left out of the verdict (unit_pair). The pair splits by ~√r (r the
  /// orbit's residual: ≤ 1e-5 at the default shooting tolerance) and, where a contact opens (the
  /// Hertz force is only C¹ there), further: 2.8e-3 on the 41-bead light-centred gap branch's
  /// first point with an open contact. A multiplier beyond the window counts, and so does a third
  /// within it. ARPACK's k largest need not hold the pair: then up to two of its multipliers
  /// within the window are left out, which hides an instability weaker than 1 + window.
  double unit_pair_window = 1e-2;
  /// ARPACK: the largest measured Ritz residual ‖M z − μ z‖/(|μ| ‖z‖) of a trusted multiplier;
  /// beyond it the set is incomplete.
  double ritz_residual_limit = 1e-6;
};

struct FloquetSpectrum {
  /// The eigenvalues of the monodromy matrix by |μ| descending: all 2N (dense) or the k of largest
  /// modulus (ARPACK; k + 1 when a complex pair straddles the k-th)
  std::vector<std::complex<double>> multipliers;
  /// "dense", "arpack", or automatic's fallback: "dense (ARPACK converged none)" or "dense (ARPACK
  /// incomplete within the dense method's cost)". Which computed them.
  std::string method = "dense";
  /// tangent integrations of one period (2N for dense; automatic's fallback adds ARPACK's attempt)
  long operator_applications = 0;
  int restarts = 0;  ///< ARPACK's implicit restarts (0 for dense; automatic's fallback: its attempt's)
  /// false when ARPACK ran out of restarts with fewer than k multipliers converged, or a Ritz
  /// residual exceeded ritz_residual_limit: the multipliers are then a part of the largest only.
  /// Stable orbits are the hard case (every |μ| = 1: no modulus gap), e.g. a stable gap breather
  /// of 101 beads needs ~150 restarts of a 40-vector basis.
  bool complete = true;
  /// max |μ| over all but the phase/family pair (unit_pair: a Jordan block that a residual r of
  /// the orbit splits by ~√r, not an instability)
  double max_modulus = 0;
  /// complete and max_modulus ≤ 1 + tolerance: an incomplete set is never called stable
  bool stable = false;
  double tolerance = 0;  ///< of `stable`
  /// "none", "real" (a real multiplier > 1: exponential instability), "oscillatory" (a complex
  /// quartet off the circle) or "unknown" (an incomplete set with no multiplier above 1 + tolerance).
  std::string instability = "none";
  double growth_rate = 0;  ///< ln(max_modulus)/T [1/s]: how fast the worst perturbation grows
  /// Symplectic checks (dense): max over μ of min_ν |ν − 1/μ| (reciprocal pairs) relative to
  /// max(1, |μ|), and |Π μ − 1|; NaN for ARPACK (not computable from the largest |μ|).
  double reciprocal_error = 0;
  double product_error = 0;
  /// The distance from +1 of the second multiplier of the phase/family pair (NaN when fewer than
  /// two lie within unit_pair_window).
  double unit_pair_distance = 0;
  /// ARPACK, per multiplier (empty for dense): dnaupd's Ritz estimate of its residual, relative to
  /// |μ|, and the residual ‖M z − μ z‖/(|μ| ‖z‖) of its Ritz vector z measured by applying M again
  /// (a restored conjugate partner shares its partner's: M is real).
  std::vector<double> ritz_estimates;
  std::vector<double> ritz_residuals;
  double ritz_residual = std::numeric_limits<double>::quiet_NaN();  ///< the largest of ritz_residuals (NaN: dense)
};

/// The phase/family pair among `multipliers`: the indices of the two nearest +1 among those within
/// `window` of it (fewer when fewer lie there), nearest first. Both methods leave them out of the
/// verdict.
std::vector<std::size_t> unit_pair(const std::vector<std::complex<double>>& multipliers, double window);

/// The multipliers of a monodromy matrix of `beads` beads (2N × 2N, consumed), the orbit's period
/// T [s] for the growth rate. Throws NumericalError if dgeev fails.
FloquetSpectrum floquet_spectrum(std::vector<double> monodromy, std::size_t beads, double period,
                                 double tolerance = 1e-6, double unit_pair_window = 1e-2);

/// M w for one vector w (2N, coordinates (δu, δv/ω_b)): one tangent integration of the period.
std::vector<double> apply_monodromy(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit,
                                    const std::vector<double>& w);

/// The k = config.multipliers multipliers of largest modulus by ARPACK (dnaupd/dneupd, mode 1) on
/// apply_monodromy, and the verdict on them. Throws InvalidInput (multipliers, subspace,
/// arpack_tolerance, max_restarts) or NumericalError (no multiplier converged within max_restarts).
FloquetSpectrum largest_floquet_multipliers(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit,
                                            const FloquetConfig& config);

/// As largest_floquet_multipliers, but when no multiplier converged within max_restarts the
/// spectrum is empty (complete = false, with the operator applications spent) instead of an error.
FloquetSpectrum try_largest_floquet_multipliers(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit,
                                                const FloquetConfig& config);

/// ARPACK's Krylov basis size (ncv) for `config` on a chain of `beads`: FloquetConfig::subspace.
int floquet_subspace(const FloquetConfig& config, std::size_t beads);

/// monodromy_matrix then floquet_spectrum (dense).
FloquetSpectrum floquet_stability(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit,
                                  double tolerance = 1e-6, double unit_pair_window = 1e-2);

/// Dense or ARPACK by config.method (automatic: by N against config.max_dense_beads; up to
/// config.max_fallback_beads ARPACK gets the dense method's cost, about 2N applications, and the
/// dense method follows when it has not converged every multiplier within it).
FloquetSpectrum floquet_stability(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit,
                                  const FloquetConfig& config);

}  // namespace granular
