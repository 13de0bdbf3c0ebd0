#pragma once
// The ensemble of bead-type correlations (docs/physics.md, "Correlations of the type sequence"): the mean and spread over
// realizations of the Pearson coefficient ρ(d) of a configuration with its cyclic shift by d,
// beside the infinite-chain formula the ensemble mean should approach. Chains of the paper's two
// types correlate the type indicator (type 1 → 0, type 2 → 1); chains of k types or polydisperse
// radii (a BeadDistribution) correlate the per-bead mass, which for two types is the same
// coefficient (Pearson is invariant under the affine map from indicator to mass).
#include <cstdint>
#include <optional>
#include <vector>

#include "granular/case/chain_choices.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/model/chain_recipe.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

struct CorrelationConfig {
  /// The chains: the paper's two types drawn by A, RDM1 or RDM2 (h has one type: no coefficient),
  /// ρ(d) of the types; or drawn from a bead distribution, ρ(d) of the per-bead masses.
  ChainRecipe chain{};
  std::size_t realizations = 100;
  std::size_t max_distance = 10;  ///< largest shift d, < N
};

struct CorrelationResult {
  std::vector<double> mean;       ///< ρ(d) averaged over the realizations used, d = 0 … max_distance
  std::vector<double> deviation;  ///< their sample standard deviation (0 with one realization)
  std::vector<double> theory;     ///< infinite-chain ρ(d) (NaN where undefined)
  std::size_t used = 0;           ///< realizations with two kinds of bead (a one-kind chain has no ρ and is skipped)
};

/// Throws InvalidInput (naming the field) on a bad config.
void validate(const CorrelationConfig& config);

/// The study's own parameters over CorrelationConfig: `realizations` and `max_distance`.
const ParameterTable<CorrelationConfig>& correlation_parameters();

/// The chains from a front end's chain choices (the correlations tool's options,
/// granular.correlations' keywords; their defaults: correlation_chain_defaults()), by one rule:
/// the two-type draw's disorder, q, N and seed (set_study_draw), or a bead distribution (`types`,
/// `type_masses`, `polydisperse`; `disorder` their rule) instead of the two types. Throws
/// InvalidInput naming the choice.
void set_chain(CorrelationConfig& c, const ChainChoices& beads);

/// The chain choices of CorrelationConfig{}.chain: what front ends show as the study's chain defaults.
ChainChoices correlation_chain_defaults();

/// Bit-identical for any thread count (run.threads; run.progress advanced per realization).
/// Throws InvalidInput when every realization has one bead type only.
CorrelationResult correlation_study(const CorrelationConfig& config, const RunOptions& run = {});

}  // namespace granular
