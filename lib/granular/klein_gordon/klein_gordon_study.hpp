#pragma once
// The `klein-gordon` job in one call: the realizations of a KleinGordonCase (klein_gordon_run.hpp:
// SABA2C, m2, P and Λ at the sample times) and their means, and the run's description. The tool and
// granular.klein_gordon are parse → this → write.
#include <cstdint>
#include <optional>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/klein_gordon/klein_gordon_case.hpp"
#include "granular/klein_gordon/klein_gordon_exponents.hpp"
#include "granular/klein_gordon/klein_gordon_run.hpp"

namespace granular {

struct KleinGordonResult {
  KleinGordonEnsemble ensemble;                   ///< each realization and the means (one realization: its own curves)
  std::vector<std::uint64_t> sample_steps;        ///< the steps sampled (sample_steps(case))
  double max_energy_error = 0;                    ///< over realizations and samples, of |H − H(0)| / H(0)
  std::optional<KleinGordonExponents> exponents;  ///< over the case's `fit` window; none without one
};

/// Validates `c` and runs it: klein_gordon_ensemble(run_config(c), c.realizations, c.threads),
/// and with a `fit` window its klein_gordon_exponents.
KleinGordonResult klein_gordon_study(const KleinGordonCase& c);

/// The run's metadata: the case (describe_rows of klein_gordon_parameters()), the scheme, the
/// sample rule and count, the observables' definitions, the largest energy error and, with a
/// `fit` window, "exponents" (describe(KleinGordonExponents…)).
nlohmann::json describe(const KleinGordonCase& c, const KleinGordonResult& r);

}  // namespace granular
