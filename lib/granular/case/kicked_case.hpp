#pragma once
// A kicked-chain case as front ends choose it — the chain in words (chain_choices.hpp) and the
// TransportCase their other options set, its kick and realizations included — made one case by
// one rule, for the `spreading` tool and granular.transport alike; or whole from a case file (a
// replay file, a run's JSON). With chain.auto_n (the tool's --N auto) N is sized from T so that
// no wave reaches a wall (chain_length_rule.hpp). Errors name the choice in the library's words
// (`realizations`, `site`, `radii`, `ic`); each front end tells it in its own.
#include <cstdint>
#include <string>
#include <vector>

#include "granular/case/chain_choices.hpp"
#include "granular/case/transport_case.hpp"
#include "granular/case/transport_parameters.hpp"
#include "granular/model/selected_chain.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

struct KickedCase {
  TransportCase c;
  SelectedChain selected;             ///< realization chain.realization (with auto_n, its "N_rule")
  std::vector<std::string> warnings;  ///< implausible radii, in the caller's names
};

/// The chain choices of a kicked case before any is given: ChainChoices' own, with N = 2501 (the
/// paper's). Against them a choice counts as given (chain_recipe's `defaults`), and front ends
/// show them as their defaults (the spreading tool's --N, granular.transport's N).
ChainChoices kicked_chain_defaults();

/// The case `run` is with the chain `chain` (realization chain.realization), before validation
/// (outputs may still add observers to it; validate_and_settle then settles the step and, for
/// integrator auto, the scheme: the case stands for SABA2C until then). `run` gives the kick, its
/// mode, the dynamics and the realizations. `ensemble`: it averages realizations, so its chains
/// must be random (not a types or radii file). `names`: how the caller's user names the radii, for
/// the warnings. E_n(T) is averaged over no realization unless the caller sets
/// c.profile_realizations. With chain.auto_n, N is sized from T so that no wave reaches a wall.
KickedCase kicked_case(const ChainChoices& chain, const TransportCase& run, bool ensemble, const RadiusNames& names);

/// The case of the case file at `path` (read_case_file), realization `realization` of its chains,
/// run over `realizations`, its deviation vector sampled `deviation_samples` times (0: none).
KickedCase kicked_case(const std::string& path, long long realization, long long realizations,
                       long long deviation_samples, bool ensemble);

}  // namespace granular
