#pragma once
// One chain recipe: everything that says which chain "realization r" is, for every study, tool
// and Python call. A recipe draws the paper's two bead types (radii R1 and ξ R1, by a disorder
// rule with probability q), or beads from a distribution (k types, polydisperse radii), or holds
// a given sequence of types or of radii (a configuration or radii file), or makes a quasiperiodic
// chain: exactly one source, a ChainSource. Random recipes are pure functions of (seed, r): the
// same chain on any machine, thread or rank. A new kind of chain is one more alternative of
// ChainSource and a case of each std::visit in chain_recipe.cpp (the compiler lists them).
//
//   granular::ChainRecipe recipe{.source = granular::TwoTypeDraw{.disorder = granular::Disorder::rdm2, .q = 0.8},
//                                .N = 1000, .seed = 7};
//   for (std::uint64_t r = 0; r < 100; ++r) { granular::Chain chain = recipe.chain(r); ... }
//
// Beads count from 0 here (chain.hpp); files and the tools count from 1.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/model/bead_distribution.hpp"
#include "granular/model/bead_source.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"
#include "granular/model/material.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/model/quasiperiodic.hpp"

namespace granular {

/// What ends a recipe's chain. Flat walls (the paper's) make the end bonds stiffer than the
/// bulk ones (a sphere on a flat has twice the effective radius of two equal spheres); sphere
/// walls are fixed beads of the end beads' radius and material, so a homogeneous chain is the
/// textbook fixed-end lattice, ω_j = 2 √(B/m) sin(jπ / (2(N+1))), exactly.
enum class WallShape { flat, sphere };

/// The walls as descriptions say them (the JSON "walls" entry).
const char* walls_description(WallShape walls);
/// "flat" or "sphere" (the tools' and Python's word); throws InvalidInput("walls") otherwise.
WallShape parse_wall_shape(const std::string& word);

/// The paper's chains: two bead types of radii R1 and ξ R1, drawn by a disorder rule.
struct TwoTypeDraw {
  Disorder disorder = Disorder::anderson;  ///< homogeneous, Anderson, random dimer 1 or 2
  double q = 0.5;        ///< probability of a type-1 bead (A), dimer "11" (RDM1) or "12" (RDM2), in [0, 1]
  double xi = 0.5;       ///< size ratio R2/R1 in (0, 1]
  bool centred = false;  ///< drawn outward from the centre bead (centred_configuration.hpp)
};

/// One given sequence of the two bead types 1 and 2 (a types file), radii R1 and ξ R1.
struct GivenTypes {
  Configuration types{};
  double xi = 0.5;     ///< size ratio R2/R1 in (0, 1]
  std::string file{};  ///< the file they were read from ("" when given in code)
};

/// One given sequence of radii [m] (a radii file).
struct GivenRadii {
  std::vector<double> radii{};
  std::string file{};  ///< the file they were read from ("" when given in code)
};

/// Where a chain's beads come from: exactly one of the paper's two-type draw, a bead distribution
/// (k types or polydisperse radii, drawn per realization), given types, given radii, or a
/// quasiperiodic chain (quasiperiodic.hpp; its beads have radius R1, realization r its phase).
using ChainSource = std::variant<TwoTypeDraw, BeadDistribution, GivenTypes, GivenRadii, Quasiperiodic>;

struct ChainRecipe {
  ChainSource source{};               ///< the beads (default: the paper's Anderson draw)
  double R1 = paper_r1;               ///< type-1 radius [m] (two types); every bead's (quasiperiodic)
  std::size_t N = 100;                ///< beads of a drawn chain (a given one has its own length)
  double F0 = 10;                     ///< static precompression [N], ≥ 0 (0: the sonic vacuum)
  Material material = steel;          ///< beads and walls
  WallShape walls = WallShape::flat;  ///< flat walls, or fixed spheres like the end beads
  std::uint64_t seed = 1;             ///< random seed of drawn chains

  /// The source if it is an `S`, else null.
  template <class S>
  S* as() {
    return std::get_if<S>(&source);
  }
  template <class S>
  const S* as() const {
    return std::get_if<S>(&source);
  }
  /// The two-type draw. Throws InvalidInput("chain") for another source (a study over q or ξ).
  TwoTypeDraw& draw();
  const TwoTypeDraw& draw() const;

  /// True when realization r matters (draws, distributions, quasiperiodic phases).
  bool drawn() const { return !as<GivenTypes>() && !as<GivenRadii>(); }
  /// The number of beads of every realization.
  std::size_t size() const;
  /// True when realization r is a sequence of the two bead types (two-type draws, given types):
  /// what studies over (q, ξ) grids need.
  bool typed() const { return as<TwoTypeDraw>() || as<GivenTypes>(); }
  /// The size ratio ξ of a typed() recipe (NaN for another).
  double xi() const;
  /// The bead types (1 or 2) of realization r: two-type draws and given types; empty otherwise.
  Configuration types(std::uint64_t r) const;
  /// The radii [m] of realization r.
  std::vector<double> radii(std::uint64_t r) const;
  /// Realization r: its masses, contacts and static overlaps.
  Chain chain(std::uint64_t r) const;
  /// The chain of given bead types under this recipe's ξ, R1, F0 and material (what chain(r)
  /// builds from types(r); a study that varies only ξ draws the types once).
  Chain chain_of(const Configuration& types) const;
  /// Realization r as a stream of beads, for methods that walk a chain once (transfer matrices):
  /// a streamed() recipe costs memory O(1) whatever N (up to 1e12); the others store the chain.
  std::unique_ptr<BeadSource> beads(std::uint64_t r) const;
  /// True when beads() draws the chain a piece at a time: two-type draws between flat walls.
  bool streamed() const { return as<TwoTypeDraw>() && !as<TwoTypeDraw>()->centred && walls == WallShape::flat; }
  /// The largest N validate() should allow: 1e12 for a streamed() recipe walked once, else 1e8.
  std::size_t largest_walked_size() const { return streamed() ? 1000000000000 : 100000000; }
  /// Every radius a bead of any realization can have, sampled (the two types, the k types of
  /// positive probability, nine points across a polydisperse range, the given radii): what a
  /// worst-case rule over every realization must try.
  std::vector<double> possible_radii() const;
};

/// The kind of chain a recipe's source makes, in one word (the IPR map's "disorder" column): the
/// draw's rule (h, A, RDM1, RDM2), types or polydisperse (a distribution), config or radii (given
/// beads), quasi-KIND.
std::string source_name(const ChainRecipe& recipe);

/// Throws InvalidInput naming the field (N, q, xi, F0, R1, material, beads, radii, types; the
/// quasiperiodic fields of quasiperiodic.hpp).
/// `max_beads`: the largest N allowed (a stored chain: 1e8; a streamed two-type draw: 1e12).
void validate(const ChainRecipe& recipe, std::size_t max_beads = 100000000);

/// The recipe as the tools' JSON "chain" entry: F0_N, material, walls, N, and what picked the
/// chain (beads + seed; radii_file; R1_m, xi and config_file or disorder, q, seed), with
/// `realization` for drawn chains when given.
nlohmann::json describe(const ChainRecipe& recipe, std::optional<std::uint64_t> realization = std::nullopt);

/// The recipe as a kicked-chain case spells it among its other fields (study/transport_study):
/// disorder, q, xi, N, F0_N, R1_m, seed, material, walls, and beads / chain_draw / config_file /
/// radii_file when they apply, a file with the hash of the values read from it (config_file_hash,
/// radii_file_hash: FNV-1a 64, hex).
void describe_fields(const ChainRecipe& recipe, nlohmann::json& fields);
/// The inverse of describe_fields (files are read again). Throws InvalidInput naming the key; a
/// file whose values no longer match its recorded hash is refused naming config_file or
/// radii_file and its path (replay and resume after an edit).
ChainRecipe parse_recipe_fields(const nlohmann::json& fields);

}  // namespace granular
