#include "granular/study/exponent_choices.hpp"

#include <optional>
#include <utility>

#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/model/disorder.hpp"

namespace granular {
namespace {

/// The chain kinds `chains` names: none for "none" alone.
bool no_chain_kinds(const std::vector<std::string>& chains) { return chains.size() == 1 && chains[0] == "none"; }

/// `words` joined by commas.
std::string comma_joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ",") + w;
  return out;
}

/// The chain beyond the kinds that `o` asks for, if any, under its name.
std::optional<BeadChain> chain_of_ones_own(const ExponentChoices& o) {
  ChainChoices drawn = o.beads;
  const ChainChoices plain;  // the draw's own choices belong to the kinds' chains, not to this one
  drawn.q = plain.q, drawn.xi = plain.xi, drawn.r1 = plain.r1;
  const bool typed = !drawn.types.empty() || !drawn.type_masses.empty();
  if (!o.types_rule.empty() && !typed)
    throw InvalidInput("types_rule", " '" + o.types_rule + "': only with `types` or `type_masses`");
  drawn.disorder = o.types_rule.empty() ? "A" : o.types_rule;
  try {
    parse_disorder(drawn.disorder);
  } catch (const InvalidInput&) {  // the parser names `disorder`, which means the chain kinds here
    throw InvalidInput("types_rule", " '" + drawn.disorder + "': expected A, RDM1 or RDM2");
  }
  const std::string& name = o.chain_name;
  if (const auto q = quasiperiodic(drawn, ExponentChoices{}.beads))
    return BeadChain{name.empty() ? "quasi-" + to_string(q->kind) : name, {}, *q};
  if (const auto beads = bead_distribution(drawn)) {
    const bool types = beads->kind == BeadDistribution::Kind::types;
    return BeadChain{name.empty() ? (types ? "types" : "polydisperse") : name, *beads};
  }
  if (!name.empty())
    throw InvalidInput("chain_name", " '" + name + "': only with `types`, `type_masses`, `polydisperse` or `quasi`");
  return std::nullopt;
}

void read_chains(ExponentChoices& o, const std::string& text) { o.chains = parse_word_list(text, "chains"); }
std::string write_chains(const ExponentChoices& o) { return chain_list(o); }
void read_kicks(ExponentChoices& o, const std::string& text) { o.ic = parse_word_list(text, "ic"); }
std::string write_kicks(const ExponentChoices& o) { return kick_list(o); }

}  // namespace

const ParameterTable<ExponentChoices>& exponent_parameters() {
  using O = ExponentChoices;
  static const ParameterTable<O> table{
      {"chains",
       {},
       {read_chains, write_chains},
       "chain kinds: comma list of h, A, RDM1, RDM2, or 'none' (only the chain of `types`/`polydisperse`)"},
      {"ic", {}, {read_kicks, write_kicks}, "kicks: comma list of displacement, velocity, mode (`mode` or `near_khz`)"},
      {"types_rule", &O::types_rule,
       "how `types`/`type_masses` are drawn: A (each bead, the default), RDM1 (each dimer), RDM2 (two types: dimers "
       "12 or 21)",
       false},
      {"chain_name", &O::chain_name,
       "the name of the chain of `types`/`type_masses`/`polydisperse`/`quasi` in the outputs (its 'disorder' "
       "column; default: types, polydisperse or quasi-KIND); it runs after the `chains` kinds, R realizations (R "
       "phases for `quasi` without `phase`)",
       false}};
  return table;
}

void apply(const ExponentChoices& o, ExponentTableConfig& config) {
  config.chains.clear();
  for (const std::string& name : no_chain_kinds(o.chains) ? std::vector<std::string>{} : o.chains) {
    try {
      config.chains.push_back(parse_disorder(name));
    } catch (const InvalidInput& e) {  // the parser names a single chain's `disorder`
      throw InvalidInput("chains", e.problem());
    }
  }
  config.kicks.clear();
  for (const std::string& name : o.ic) config.kicks.push_back(parse_kick(name));
  if (config.kicks.empty()) throw InvalidInput("ic", ": none given");
  config.bead_chains.clear();
  if (auto chain = chain_of_ones_own(o)) config.bead_chains.push_back(std::move(*chain));
  ChainChoices kinds = o.beads;  // the kinds' chains, by the one chain rule: without the chain of one's own
  kinds.types.clear(), kinds.type_masses.clear(), kinds.polydisperse.clear(), kinds.quasi.clear();
  kinds.config.clear(), kinds.radii.clear();
  const ChainChoices plain;  // nor its quasiperiodic parameters (its own chain has taken them)
  kinds.modulation = plain.modulation, kinds.ratio = plain.ratio, kinds.phase = plain.phase;
  kinds.angle = plain.angle, kinds.k0 = plain.k0, kinds.k0_n_per_m = plain.k0_n_per_m;
  std::vector<std::string> no_file_read;
  config.base.chain = chain_recipe(kinds, no_file_read);
  refuse_mode_without_mode_kick(o.mode, config.kicks);
  config.base.mode = o.mode;
  validate(config);
}

std::string chain_list(const ExponentChoices& o) {
  return o.chains.empty() || no_chain_kinds(o.chains) ? "none" : comma_joined(o.chains);
}

std::string kick_list(const ExponentChoices& o) { return comma_joined(o.ic); }

}  // namespace granular
