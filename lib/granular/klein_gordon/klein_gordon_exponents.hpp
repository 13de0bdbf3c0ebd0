#pragma once
// The DKG chain's exponents over a window [t0, t1] (docs/physics.md, "The disordered Klein–Gordon
// chain"): m2 ∝ t^α, P ∝ t^α_P and Λ ∝ t^α_Λ, each the least-squares slope in log–log over the
// samples inside (power_law_fit.hpp: loglog_slope, log_time_slope). Of an ensemble, the slope of
// the mean curve (of ⟨log10 Λ⟩ for Λ, as the field averages it) and, beside it, each
// realization's own slope: their mean ± standard error std/√R says how much the slope varies
// from one disorder to the next.
//
//   auto x = granular::klein_gordon_exponents(ensemble, 1e3, 1e5);   // x.alpha.curve, x.alpha.mean
#include <cstddef>
#include <limits>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/klein_gordon/klein_gordon_run.hpp"

namespace granular {

struct KleinGordonSlope {
  double curve = std::numeric_limits<double>::quiet_NaN();  ///< slope of the (mean) curve
  /// Of the realizations' own slopes (R ≥ 2; NaN otherwise): mean and standard error std/√R (std with R − 1).
  double mean = std::numeric_limits<double>::quiet_NaN();
  double error = std::numeric_limits<double>::quiet_NaN();
};

struct KleinGordonExponents {
  double begin = 0, end = 0;      ///< the window [1/ω₀]
  std::size_t samples = 0;        ///< samples inside it
  KleinGordonSlope alpha;         ///< of m2
  KleinGordonSlope alpha_P;       ///< of P
  KleinGordonSlope alpha_Lambda;  ///< of Λ (⟨log10 Λ⟩); NaN without Λ or where a Λ ≤ 0 in the window
};

/// The exponents of `e` over [t0, t1]. Throws InvalidInput naming `fit` unless 0 < t0 < t1 and
/// at least 3 samples lie inside.
KleinGordonExponents klein_gordon_exponents(const KleinGordonEnsemble& e, double t0, double t1);

/// {fit: [t0, t1], samples, alpha, alpha_P, alpha_Lambda (with Λ) and, for R ≥ 2, each one's
/// realization mean and standard error as <name>_mean, <name>_error}; NaN is null.
nlohmann::json describe(const KleinGordonExponents& x, std::size_t realizations, bool lambda);

}  // namespace granular
