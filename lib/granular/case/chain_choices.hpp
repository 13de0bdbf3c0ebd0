#pragma once
// One chain as a front end takes it in words and numbers — the tools' chain options — turned
// into a ChainRecipe by one rule: a random two-type draw (disorder, q, ξ, R1), a types or radii
// file, k types or polydisperse radii in their text forms (io/bead_distribution_syntax.hpp), or a
// quasiperiodic chain. Errors name the choice in the library's vocabulary (`seed`, `types`,
// `type_masses`, `polydisperse`, `quasi`, `ratio`); each front end tells it in its own words.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "granular/model/bead_distribution.hpp"
#include "granular/model/chain_recipe.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/model/plausibility.hpp"
#include "granular/model/quasiperiodic.hpp"
#include "granular/model/selected_chain.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

struct ChainChoices {
  std::string disorder = "A";     ///< h | A | RDM1 | RDM2 (also the rule of k types)
  double xi = 0.5;                ///< size ratio R2/R1 in (0, 1]
  double q = 0.5;                 ///< probability of a type-1 bead (A), dimer 11 (RDM1) or 12 (RDM2)
  double f0 = 10;                 ///< static precompression F0 [N]
  double r1 = paper_r1;           ///< type-1 radius R1 [m]
  long long n = 100;              ///< beads N (≥ 2)
  long long seed = 1;             ///< random seed (≥ 0)
  long long realization = 0;      ///< which realization of the seed (0-based, ≥ 0)
  std::string config{};           ///< file of bead types 1 and 2 ("" = none)
  std::string radii{};            ///< file of radii [m] ("" = none)
  std::string types{};            ///< k types "R1:P1,R2:P2,…" (radius [m]: probability), "" = none
  std::string type_masses{};      ///< k types "M1:P1,…" (mass [kg] of a steel sphere: probability), "" = none
  std::string polydisperse{};     ///< "uniform:LO:HI" or "normal:MEAN:SD:MIN" [m], "" = none
  std::string walls = "flat";     ///< flat | sphere
  std::string quasi{};            ///< s1 | s2 | cylinders: a quasiperiodic chain ("" = none)
  std::string ratio = "golden";   ///< its incommensurate ratio β > 0: golden, p/q or a number
  double modulation = 0;          ///< its relative modulation λ, |λ| < 1
  double angle = 45;              ///< cylinders: mean crossing angle α0 [degrees]
  double k0 = 4;                  ///< s1: mean on-site stiffness [bond stiffness K]
  double k0_n_per_m = 0;          ///< s1: mean on-site stiffness [N/m] instead of k0 (0: use k0)
  std::optional<double> phase{};  ///< its phase [rad]; none: drawn per seed and realization
  bool auto_n = false;            ///< N sized later for long times, the chain drawn from its centre
};

/// Each choice's meaning and units (parameter_table.hpp), in the order front ends show them: the
/// random two-type draw, the files, the bead distributions, the quasiperiodic chain. Not `auto_n`
/// (a front end's own word for N).
const ParameterTable<ChainChoices>& chain_parameters();

/// The quasiperiodic chain of the choices, if `quasi` is given. Throws InvalidInput naming
/// `quasi` or `ratio`, or naming the second of `config`, `radii`, `types`, `type_masses`,
/// `polydisperse` and `quasi` given (a chain comes from one of them; bead_distribution too), or a
/// choice given without what it needs or with what overrides it (refuse_unmet_needs). `defaults`:
/// the front end's own defaults of the choices, against which "given" is told (a kicked case's N
/// is 2501, the localization tool's 1e6).
std::optional<Quasiperiodic> quasiperiodic(const ChainChoices& o, const ChainChoices& defaults = {});

/// The distribution of `types`, `type_masses` or `polydisperse` (the first given; rule:
/// `disorder`), if one is. Throws InvalidInput naming the choice.
std::optional<BeadDistribution> bead_distribution(const ChainChoices& o);

/// The recipe of the choices, files read (not yet validated: a streamed chain has its own limits;
/// `seed`, `realization` and `n` are checked here). Each implausible radius of a radii file is
/// a line of `warnings` (file and line named). `defaults`: as for quasiperiodic().
ChainRecipe chain_recipe(const ChainChoices& o, std::vector<std::string>& warnings, const ChainChoices& defaults = {});

/// How a front end's user names the choices that set radii, for the warnings about implausible
/// ones (model/plausibility.hpp): `R1`, the bead distribution given (`types`, `type_masses` or
/// `polydisperse`) and `radii`, each told by `told` (a tool: its flag; Python: its keyword).
RadiusNames radius_names(const ChainChoices& o, const std::function<std::string(const std::string&)>& told);

/// The choices of a two-type draw's recipe (disorder, q, ξ, N, F0, R1, seed, walls; the rest
/// ChainChoices' own): a study's default chain (IprMapConfig{}.chain, CorrelationConfig{}.chain)
/// in the words of the chain table, whose defaults a front end shows (granular.ipr_map's chain
/// keywords). Throws InvalidInput("chain") for another source.
ChainChoices chain_choices(const ChainRecipe& draw);

/// The two-type draw of a study's chains from the choices (the study tools' --disorder, --q, --N,
/// --F0, --R1, --seed and --walls; granular.ipr_map's and correlations' keywords): those numbers
/// into `chain` (N 2 … 1e8; its ξ stays the recipe's, a map's q and ξ are each cell's). Throws
/// InvalidInput naming the choice.
void set_study_draw(ChainRecipe& chain, const ChainChoices& o);

/// The choices with the draw's own numbers (q, ξ, N, F0, R1, seed) at ChainChoices' defaults: what
/// a study reads its chain kind from (a quasiperiodic chain, a bead distribution), so that R1
/// beside `types`, or a seed with disorder h, is taken as set_study_draw takes it rather than
/// refused by the chain table's overrides.
ChainChoices chain_kind_choices(ChainChoices o);

/// The realization the choices pick (0-based).
inline std::uint64_t chain_realization(const ChainChoices& o) { return static_cast<std::uint64_t>(o.realization); }

/// The chain the choices pick, walked once rather than stored where it can be (stream_chain,
/// model/selected_chain.hpp): a tool's chain options and a Python call's chain keywords make it
/// by this one rule. Warnings (a radii file's implausible radii) name the choices as `told`
/// tells them (a tool: its flag; Python: its keyword). Throws InvalidInput naming the choice.
/// `defaults`: as for quasiperiodic().
StreamedChain stream_chain(const ChainChoices& o, const std::function<std::string(const std::string&)>& told,
                           const ChainChoices& defaults = {});

}  // namespace granular
