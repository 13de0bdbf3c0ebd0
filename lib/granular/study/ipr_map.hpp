#pragma once
// Mean frequency and IPR of every mode over realizations, on a grid of (q, ξ) (docs/physics.md, "The linear spectrum"; the
// paper's IPR-map figure), or the selected modes (nearest/window) of every realization.
// Realization r of a cell uses the bead types of realization r of the seed, so all ξ of one q
// share their configurations (common random numbers).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "granular/case/chain_choices.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/chain_recipe.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

/// The paper's ξ axis of the IPR map: 0.1, 0.11, …, 1 (the range "0.1:1:0.01", rounded as
/// range_syntax.hpp rounds a range).
std::vector<double> paper_xi_values();

struct IprMapConfig {
  /// The chains (N, F0 > 0, seed, R1, material; the disorder rule or a bead distribution); its
  /// q and ξ are those of each cell, from the lists below.
  ChainRecipe chain{};
  std::vector<double> q_values{0.2, 0.5, 0.8};        ///< probabilities in [0, 1]
  std::vector<double> xi_values = paper_xi_values();  ///< size ratios R2/R1 in (0, 1]
  std::size_t realizations = 100;
  /// Every mode (averaged over realizations by mode number) or a nearest/window selection (every
  /// selected mode of every realization, not averaged: mode numbers and counts differ between chains).
  ModeSelection selection = all_modes();
  /// The solver: every mode by fast (default) or lapack; a selection by lapack, bisect or arpack
  /// (arpack runs on one thread: ARPACK keeps state in Fortran SAVE variables; slepc is refused:
  /// the map solves one chain per thread, while SLEPc is collective over MPI ranks).
  SpectrumConfig spectrum{.method = SpectrumMethod::fast};
  /// The solver as a front end names it, which set_solver turns into `spectrum`: fast | lapack |
  /// lapack-<stevr|stemr|stevd|steqr> for every mode; and for a selection, `method` lapack |
  /// bisect | arpack ("": lapack).
  std::string solver = "fast";
  std::string method{};
  /// Every mode only: 0 averages over realizations by mode number (the default); W > 0 [kHz]
  /// averages in frequency bins [k W, (k + 1) W), k = 0 … ⌊f_max / W⌋, f_max the highest mode
  /// of the cell's realizations: the ensemble's IPR as a function of f, which is what a reader
  /// plotting against frequency wants (mode-number means put points inside band gaps).
  double bin_khz = 0;
  // With chain.distribution set, realization r draws its radii from it (k types or
  // polydisperse) instead of the two types: one cell, whose q and xi are NaN.
};

struct IprMapCell {
  double q = 0, xi = 0;
  std::vector<double> freq_khz;  ///< every mode: mean over realizations, mode k at index k-1
  std::vector<double> ipr;       ///< every mode: mean over realizations
  /// With a selection: every selected mode of every realization is one row, realization-major,
  /// by increasing frequency; `mode` holds its mode number and `realization` its realization.
  /// Both stay empty for every mode.
  std::vector<std::size_t> mode;
  std::vector<std::uint64_t> realization;
  /// With bin_khz > 0 (every mode): bin b is [b·bin_khz, (b+1)·bin_khz) kHz; bin_modes[b] counts
  /// the modes of all realizations in it, bin_ipr[b] is their mean IPR (NaN when bin_modes = 0).
  std::vector<std::size_t> bin_modes;
  std::vector<double> bin_ipr;
  /// Modes solved in this cell (all realizations) and how many of them lie in a near-degenerate
  /// cluster (Spectrum::clustered: relative gap < cluster_relative_gap), whose IPR depends on the
  /// basis the solver chose inside the cluster.
  std::size_t solved_modes = 0, clustered_modes = 0;
};

/// The map's own parameters over IprMapConfig: `xi` and `q` (the grid: "start:stop[:step]",
/// step 0.01 and 0.1 by default, or comma lists), `realizations` (chains averaged per cell),
/// `solver`, `method` and `bin_khz`. The chain and the modes are set by their own rules
/// (set_chain, choose_modes), the spectrum's config from the solver's words by set_solver.
const ParameterTable<IprMapConfig>& ipr_map_parameters();

/// Throws InvalidInput (naming the field) on a bad config, before any work starts.
void validate(const IprMapConfig& config);

/// The map's chain from a front end's chain choices (the ipr-map tool's chain options,
/// granular.ipr_map's chain keywords; their defaults: ipr_map_chain_defaults()), by one rule: the
/// two-type draw's disorder, N (2 … 1e8), F0, R1 and seed (q and ξ are each cell's), the walls,
/// and a quasiperiodic chain or a bead distribution (`types`, `type_masses`, `polydisperse`;
/// `disorder` their rule) instead of the two-type draw, each a map of one cell (q = ξ = NaN) whose
/// realizations are phases or draws. Throws InvalidInput naming the choice.
void set_chain(IprMapConfig& c, const ChainChoices& beads);

/// The chain choices of IprMapConfig{}.chain (chain_choices): what front ends show as the map's
/// chain defaults.
ChainChoices ipr_map_chain_defaults();

/// c.spectrum from the words c.solver (every mode) and, for a partial selection (c.selection set
/// first: near/count or window), c.method ("": lapack), which only a selection takes. Throws
/// InvalidInput naming `solver` or `method`.
void set_solver(IprMapConfig& c);

/// One cell per (q, ξ), q-major. Bit-identical for any thread count. Uses run.threads and
/// run.progress (advanced once per chain solved); no checkpoints (the default map takes seconds).
std::vector<IprMapCell> compute_ipr_map(const IprMapConfig& config, const RunOptions& run = {});

}  // namespace granular
