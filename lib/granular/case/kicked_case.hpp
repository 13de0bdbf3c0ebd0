#pragma once
// A kicked-chain case as front ends choose it — the chain, the kick, the run's choices and how
// many realizations — turned into a TransportCase by one rule, for the `spreading` tool and
// granular.transport alike; or whole from a case file (a replay file, a run's JSON). With
// chain.auto_n (the tool's --N auto) N is sized from T so that no wave reaches a wall
// (chain_length_rule.hpp). Errors name the choice in the library's words (`realizations`,
// `site`, `radii`); each front end tells it in its own.
#include <cstdint>
#include <string>
#include <vector>

#include "granular/case/chain_choices.hpp"
#include "granular/case/transport_case.hpp"
#include "granular/case/transport_parameters.hpp"
#include "granular/model/selected_chain.hpp"

namespace granular {

struct KickedCaseChoices {
  ChainChoices chain{.n = 2501};    ///< the chains (realization: the one a single run integrates)
  std::string ic = "displacement";  ///< the kick: displacement | velocity | mode
  ModeKick mode{};                  ///< a mode kick's mode
  /// The run as transport_parameters() sets it: where the kick lands, the scheme, samples, fit,
  /// guards, damping and the tangent map (its chain, kick, mode and realizations come from here).
  TransportCase run{};
  long long realizations = 1;  ///< realizations averaged (≥ 1)
};

struct KickedCase {
  TransportCase c;
  SelectedChain selected;             ///< realization chain.realization (with auto_n, its "N_rule")
  std::vector<std::string> warnings;  ///< implausible radii, in the caller's names
};

/// The case the choices give, before validation (outputs may still add observers to it;
/// validate_and_settle then settles the step and, for integrator auto, the scheme: the case stands
/// for SABA2C until then). `ensemble`: it averages realizations, so its chains must be random
/// (not a types or radii file). `names`: how the caller's user names the radii, for the warnings.
/// E_n(T) is averaged over no realization unless the caller sets c.profile_realizations.
KickedCase kicked_case(const KickedCaseChoices& o, bool ensemble, const RadiusNames& names);

/// The case of the case file at `path` (read_case_file), realization `realization` of its chains,
/// run over `realizations`, its deviation vector sampled `deviation_samples` times (0: none).
KickedCase kicked_case(const std::string& path, long long realization, long long realizations,
                       long long deviation_samples, bool ensemble);

}  // namespace granular
