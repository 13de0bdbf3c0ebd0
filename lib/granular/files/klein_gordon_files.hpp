#pragma once
// The table of the `klein-gordon` job, so that the tool and Python write alike; the JSON is
// describe(case, result) (dynamics/klein_gordon_study.hpp).
#include <ostream>

#include "granular/dynamics/klein_gordon_study.hpp"

namespace granular {

/// t,m2,P[,mle,mean_log10_mle]: one row per sample, t [1/ω₀]; m2 [sites²], P [sites] and Λ [ω₀]
/// the means over the realizations (one realization: its own), and ⟨log10 Λ⟩; the last two only
/// when Λ was computed.
void write_klein_gordon_csv(std::ostream& out, const KleinGordonResult& r);

}  // namespace granular
