#pragma once
// The chains and kicks of the exponent table as front ends take them in words — the `exponents`
// tool's chain kinds, kicks and its one chain of k bead types, polydisperse radii or a
// quasiperiodic chain under a name of its own, the keywords of granular.exponent_table — turned
// into an ExponentTableConfig by one rule. Errors name the choice (`chains`, `ic`, `types_rule`,
// `chain_name`, or the bead chain's own field); each front end tells it in its own words.
#include <string>
#include <vector>

#include "granular/case/chain_choices.hpp"
#include "granular/case/transport_parameters.hpp"
#include "granular/study/exponent_table.hpp"

namespace granular {

struct ExponentChoices {
  /// Chain kinds h, A, RDM1, RDM2 (any case); "none" alone, or none: only the chain of `beads`.
  std::vector<std::string> chains{"h", "A", "RDM1", "RDM2"};
  std::vector<std::string> ic{"displacement", "velocity"};  ///< the kicks: displacement, velocity, mode
  /// The chains: N, xi, q, R1, seed and walls of every kind, and one more chain after the kinds:
  /// its types, type_masses, polydisperse, or quasi and that chain's parameters (not read:
  /// `disorder`, F0, the realization and the files).
  ChainChoices beads{.n = 2501};
  std::string types_rule{};  ///< how types / type_masses are drawn: A, RDM1 or RDM2; empty: A
  std::string chain_name{};  ///< that chain's name in the outputs; empty: types, polydisperse or quasi-KIND
  ModeKick mode{};           ///< the mode of `ic` mode
};

/// Each choice's meaning (parameter_table.hpp); `chains` and `ic` are lists, set by front ends in
/// forms of their own (comma lists on the command line). Not `beads`: chain_parameters().
const ParameterTable<ExponentChoices>& exponent_parameters();

/// Sets config.chains, config.kicks, config.bead_chains, config.base.chain (but its F0, set per
/// case) and config.base.mode from the choices and validates them
/// (validate(const ExponentTableConfig&)). Throws InvalidInput naming the choice.
void apply(const ExponentChoices& choices, ExponentTableConfig& config);

/// The chain kinds as the outputs' parameters list them: "h,A", or "none".
std::string chain_list(const ExponentChoices& choices);

/// The kicks as the outputs' parameters list them: "displacement,velocity".
std::string kick_list(const ExponentChoices& choices);

}  // namespace granular
