#pragma once
// From a study's cases as read to cases ready to run, with the errors in the order a user can act
// on them: first what the stability limit of τ needs (the chain, the kick, T and τ finite and
// > 0), then the step (a τ given past the limit is named as such, with the largest stable τ),
// then everything judged on the grid of that step (a fit_step or a T that is no whole number of
// steps). A τ of 1e-4 s on a 10 ms run is a stability problem first: naming fit_step instead
// would send the user to the wrong option. Then the plausibility of T (chain_length_rule.hpp)
// from the ω_max the step rule found, not found again.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/case/transport_case.hpp"
#include "granular/model/chain.hpp"

namespace granular {

/// validate_before_time_step on every case, settle_scheme_and_step (scheme_choice.hpp: what the
/// cases leave to settle, their time step and an automatic scheme, is resolved), validate on every
/// case (and the kicked `site` set to its bead's number, where 0 stood
/// for the centre), then duration_warning with the largest ω_max of the cases (they share T: one warning, of
/// the first case that draws it). `chain` as settle_scheme_and_step; `duration_option` names T in
/// the warning ("--T", "T"), which goes to `warning` ("" when T is plausible). Returns
/// settle_scheme_and_step's rule, for the JSON.
nlohmann::json validate_and_settle(std::vector<TransportCase>& cases, const std::string& duration_option,
                                   std::string& warning, const Chain* chain = nullptr);
/// The same for one case.
nlohmann::json validate_and_settle(TransportCase& c, const std::string& duration_option, std::string& warning,
                                   const Chain* chain = nullptr);

}  // namespace granular
