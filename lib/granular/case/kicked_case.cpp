#include "granular/case/kicked_case.hpp"

#include "granular/case/case_file.hpp"
#include "granular/case/chain_length_rule.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

/// Checks the realizations and sets them; an ensemble draws random chains, not a file's.
void set_realizations(KickedCase& k, long long realizations, bool ensemble) {
  if (realizations < 1) throw InvalidInput("realizations", " " + std::to_string(realizations) + ": must be >= 1");
  const ChainRecipe& chain = k.c.chain;
  if (ensemble && !chain.drawn())
    throw InvalidInput("`realizations`/`resume`: an ensemble draws random chains; `config`/`radii` give one chain");
  k.c.realizations = static_cast<std::size_t>(realizations);
  k.c.profile_realizations = 0;
  k.warnings.insert(k.warnings.end(), k.selected.warnings.begin(), k.selected.warnings.end());
}

}  // namespace

ChainChoices kicked_chain_defaults() {  // the case's own N (TransportCase{}.chain: the paper's 2501)
  return ChainChoices{.n = static_cast<long long>(TransportCase{}.chain.N)};
}

KickedCase kicked_case(const ChainChoices& chain, const TransportCase& run, bool ensemble, const RadiusNames& names) {
  if (chain.auto_n) require_centre_kick(static_cast<long long>(run.site));
  KickedCase k;  // (not an aggregate initializer: GCC 12 destroys its members twice when one throws)
  TransportCase& c = k.c;
  c = run;
  c.chain = chain_recipe(chain, k.warnings, kicked_chain_defaults());  // with auto_n, N 3 until sized below
  refuse_mode_without_mode_kick(c.mode, {c.kick});
  fit_within_duration(c);  // a window beyond T: no exponents, a note
  nlohmann::json rule;
  if (chain.auto_n) {
    validate(c.chain);                       // a drawn two-type chain
    rule = to_json(size_for_long_times(c));  // N, the centre kick, the centred draw
  }
  k.selected = select_chain(c.chain, chain_realization(chain), names);
  if (chain.auto_n) k.selected.description["N_rule"] = rule;
  set_realizations(k, static_cast<long long>(run.realizations), ensemble);
  return k;
}

KickedCase kicked_case(const std::string& path, long long realization, long long realizations,
                       long long deviation_samples, bool ensemble) {
  if (realization < 0) throw InvalidInput("realization", " " + std::to_string(realization) + ": must be >= 0");
  KickedCase k;
  k.c = read_case_file(path);
  if (deviation_samples < 0)
    throw InvalidInput("deviation_samples", " " + std::to_string(deviation_samples) + ": 0 (none) or at least 2");
  k.c.dynamics.deviation_samples = static_cast<std::size_t>(deviation_samples);  // the tangent map as the file says
  k.selected = select_chain(k.c.chain, static_cast<std::uint64_t>(realization), {"R1_m", "beads", "radii_file"});
  set_realizations(k, realizations, ensemble);
  return k;
}

}  // namespace granular
