#pragma once
// The files of a correlation study (the `correlations` tool's contract, DESIGN.md): its CSV and
// the JSON entries that describe it, so that the tool and Python write alike.
#include <ostream>

#include <nlohmann/json_fwd.hpp>

#include "granular/study/correlation_study.hpp"

namespace granular {

/// distance,rho_mean,rho_std,rho_theory for d = 0 … max_distance.
void write_correlations_csv(std::ostream& out, const CorrelationResult& result);

/// The study's JSON entries: parameters (disorder, q, N, realizations, seed, max_distance; beads
/// for a distribution), correlated (what ρ is of), realizations_used.
nlohmann::json describe_correlations(const CorrelationConfig& config, const CorrelationResult& result);

}  // namespace granular
