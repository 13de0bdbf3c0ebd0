#pragma once
// The exponent table as front ends take it: its own parameters (chain kinds, kicks, precompressions,
// realizations, profiles) as rows over ExponentTableConfig itself, and its chains in words — the
// `exponents` tool's and granular.exponent_table's chain options, with one chain of k bead types,
// polydisperse radii or a quasiperiodic chain under a name of its own — made the config's chains by
// one rule. Errors name the choice (`chains`, `ic`, `types_rule`, `chain_name`, or the bead chain's
// own field); each front end tells it in its own words.
#include <string>
#include <vector>

#include "granular/case/chain_choices.hpp"
#include "granular/case/kicked_case.hpp"
#include "granular/case/transport_parameters.hpp"
#include "granular/study/exponent_table.hpp"

namespace granular {

/// The chain of one's own beyond the kinds, in words: the exponents tool's --types/--type-masses/
/// --polydisperse or --quasi and that chain's parameters, the rule of k types and its name.
struct ExponentChoices {
  /// The chains: N, xi, q, R1, seed and walls of every kind, and one more chain after the kinds:
  /// its types, type_masses, polydisperse, or quasi and that chain's parameters (not read:
  /// `disorder`, F0, the realization and the files).
  ChainChoices beads = kicked_chain_defaults();
  std::string types_rule{};  ///< how types / type_masses are drawn: A, RDM1 or RDM2; empty: A
  std::string chain_name{};  ///< that chain's name in the outputs; empty: types, polydisperse or quasi-KIND
};

/// Each choice's meaning (parameter_table.hpp): `types_rule` and `chain_name`. Not `beads`:
/// chain_parameters().
const ParameterTable<ExponentChoices>& exponent_parameters();

/// The table's own parameters, over ExponentTableConfig itself: `chains` (kinds h, A, RDM1,
/// RDM2, any case, or 'none': only the chain of one's own), `ic` (kicks), `F0` (precompressions
/// [N]), `realizations` (per disordered case), `profile_F0` (F0s whose E_n(T) is averaged, or
/// 'none') and `profile_realizations`. The lists have text forms (comma lists; F0 also ranges).
const ParameterTable<ExponentTableConfig>& exponent_table_parameters();

/// The chain kinds `words` name (any case; "none" alone: no kind). Throws InvalidInput("chains").
std::vector<Disorder> parse_chain_kinds(const std::vector<std::string>& words);
/// The kicks `words` name. Throws InvalidInput("ic").
std::vector<Kick> parse_kicks(const std::vector<std::string>& words);

/// Sets config.bead_chains (the chain of one's own, if any) and config.base.chain (but its F0, set
/// per case) from the choices, and validates the config (validate(const ExponentTableConfig&)).
/// Throws InvalidInput naming the choice.
void set_chains(const ExponentChoices& choices, ExponentTableConfig& config);

/// The chain kinds as the outputs' parameters list them: "h,A", or "none".
std::string chain_list(const ExponentTableConfig& config);

/// The kicks as the outputs' parameters list them: "displacement,velocity".
std::string kick_list(const ExponentTableConfig& config);

}  // namespace granular
