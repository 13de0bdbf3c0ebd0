#pragma once
// The Hofstadter butterfly of a quasiperiodic chain (docs/physics.md, "Quasiperiodic chains"):
// every mode's frequency and displacement IPR for each incommensurate ratio β of a grid, one chain
// (one phase) per β, by the fast all-modes solver; and the box-counting dimension of each β's
// set of frequencies (analysis/box_counting.hpp) over a stated range of box sizes.
//
//   granular::ButterflyConfig c;
//   c.chain.N = 1000;
//   c.chain.source = granular::Quasiperiodic{.kind = granular::Quasiperiodic::Kind::s1, .modulation = 0.3};
//   c.ratios = {0.01, 0.02, …};
//   auto columns = granular::compute_butterfly(c, {});
#include <cstdint>
#include <ostream>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/analysis/box_counting.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/model/chain_recipe.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

/// The ratios a butterfly scans by default: β = 0.005, 0.010, …, 0.995.
std::vector<double> default_butterfly_ratios();

struct ButterflyConfig {
  ChainRecipe chain;  ///< a quasiperiodic recipe (chain.quasi set); its ratio is replaced by each β
  std::vector<double> ratios = default_butterfly_ratios();  ///< β values, each finite and > 0
  std::uint64_t realization = 0;                            ///< which phase of chain.seed (or the given phase)
  /// The largest box, as a fraction of each spectrum's extent f_max − f_min; 0: automatic, 5 % of
  /// it or 8 smallest boxes if more (few beads). Boxes near the extent count the ends of the set
  /// (N(ε) = ⌊L/ε⌋ + 1 for evenly spaced points): from half the extent an interval came out 0.949.
  double largest_box = 0;
  double smallest_box_spacings = 4;  ///< the smallest box, in mean level spacings (extent / N)
  std::size_t box_sizes = 12;        ///< sizes, evenly spaced in ln ε
};

/// The butterfly's own parameters over ButterflyConfig: `ratios` ("start:stop[:step]", step 0.005,
/// or a comma list), `largest_box`, `smallest_box` and `box_sizes` of the dimension fit. The chain
/// and its realization come from the chain table (the quasiperiodic rows).
const ParameterTable<ButterflyConfig>& butterfly_parameters();

/// The largest box of `config` as a fraction of the extent, for a spectrum of `modes` levels
/// (resolving largest_box = 0).
double largest_box_fraction(const ButterflyConfig& config, std::size_t modes);

/// The box sizes [units of `extent`] of the dimension fit of a spectrum of `modes` levels spanning `extent`.
std::vector<double> butterfly_box_sizes(const ButterflyConfig& config, double extent, std::size_t modes);

/// Throws InvalidInput naming the field (quasi, ratios, box fields, and the chain's own).
void validate(const ButterflyConfig& config);

/// `chain`, a quasiperiodic recipe, with its ratio replaced by β: the chain of one column.
ChainRecipe at_ratio(ChainRecipe chain, double beta);
/// Throws InvalidInput unless `chain` is quasiperiodic (naming quasi) and `ratios` are some β,
/// each finite and > 0 (naming ratios), at each of which the chain is valid (naming its field).
void validate_ratios(const ChainRecipe& chain, const std::vector<double>& ratios);

struct ButterflyColumn {
  double ratio = 0;
  std::vector<double> freq_khz;    ///< every mode, ascending [kHz]
  std::vector<double> ipr;         ///< its displacement IPR
  BoxCountingDimension dimension;  ///< of freq_khz; box sizes in kHz
};

/// One column per β, in the order given; thread-count invariant (one chain per β, fixed slots).
std::vector<ButterflyColumn> compute_butterfly(const ButterflyConfig& config, const RunOptions& run);

/// ratio,mode,freq_khz,ipr: one row per mode per β.
void write_butterfly_csv(std::ostream& out, const std::vector<ButterflyColumn>& columns);

/// The JSON entries: chain (the recipe, its ratio "each of ratios"), ratios, realization, solver,
/// and box_counting: {largest_box, smallest_box_spacings, box_sizes, ratio[], dimension[], error[],
/// box_khz_largest[], box_khz_smallest[]}.
nlohmann::json describe_butterfly(const ButterflyConfig& config, const std::vector<ButterflyColumn>& columns);

}  // namespace granular
