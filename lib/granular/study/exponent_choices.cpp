#include "granular/study/exponent_choices.hpp"

#include <optional>
#include <utility>

#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/model/disorder.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

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

using T = ExponentTableConfig;

void read_chains(T& c, const std::string& text) { c.chains = parse_chain_kinds(parse_word_list(text, "chains")); }
std::string write_chains(const T& c) { return chain_list(c); }
void read_kicks(T& c, const std::string& text) { c.kicks = parse_kicks(parse_word_list(text, "ic")); }
std::string write_kicks(const T& c) { return kick_list(c); }
void read_f0(T& c, const std::string& text) { c.precompressions = parse_number_list(text, "F0"); }
std::string write_f0(const T& c) { return format_number_list(c.precompressions); }
void read_profile_f0(T& c, const std::string& text) {
  c.profile_precompressions = text == "none" ? std::vector<double>{} : parse_number_list(text, "profile_F0");
}
std::string write_profile_f0(const T& c) {
  return c.profile_precompressions.empty() ? "none" : format_number_list(c.profile_precompressions);
}

}  // namespace

const ParameterTable<ExponentChoices>& exponent_parameters() {
  using O = ExponentChoices;
  static const ParameterTable<O> table{
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

const ParameterTable<ExponentTableConfig>& exponent_table_parameters() {
  static const ParameterTable<T> table{
      {"chains",
       {},
       {read_chains, write_chains},
       "chain kinds: comma list of h, A, RDM1, RDM2, or 'none' (only the chain of `types`/`polydisperse`)"},
      {"ic", {}, {read_kicks, write_kicks}, "kicks: comma list of displacement, velocity, mode (`mode` or `near_khz`)"},
      {"F0", {}, {read_f0, write_f0}, "precompressions [N], comma list (0 = sonic vacuum)"},
      {"realizations", path<T>(&T::base, &TransportCase::realizations),
       "realizations per disordered case (h always runs 1)"},
      {"profile_F0",
       {},
       {read_profile_f0, write_profile_f0},
       "F0s whose energy profile E_n(T) is averaged (list; 'none')"},
      {"profile_realizations", &T::profile_realizations, "realizations averaged in those profiles"}};
  return table;
}

std::vector<Disorder> parse_chain_kinds(const std::vector<std::string>& words) {
  std::vector<Disorder> kinds;
  if (words.size() == 1 && words[0] == "none") return kinds;
  for (const std::string& name : words) {
    try {
      kinds.push_back(parse_disorder(name));
    } catch (const InvalidInput& e) {  // the parser names a single chain's `disorder`
      throw InvalidInput("chains", e.problem());
    }
  }
  return kinds;
}

std::vector<Kick> parse_kicks(const std::vector<std::string>& words) {
  std::vector<Kick> kicks;
  for (const std::string& name : words) kicks.push_back(parse_kick(name));
  return kicks;
}

void set_chains(const ExponentChoices& o, ExponentTableConfig& config) {
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
  validate(config);
}

std::string chain_list(const ExponentTableConfig& config) {
  std::vector<std::string> names;
  for (Disorder d : config.chains) names.push_back(to_string(d));
  return names.empty() ? "none" : comma_joined(names);
}

std::string kick_list(const ExponentTableConfig& config) {
  std::vector<std::string> names;
  for (Kick k : config.kicks) names.push_back(to_string(k));
  return comma_joined(names);
}

}  // namespace granular
