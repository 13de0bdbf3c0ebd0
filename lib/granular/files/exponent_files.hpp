#pragma once
// The files of the paper's exponent study (the `exponents` tool's contract, DESIGN.md), one
// writer for them all, so that any program writes them exactly as the tool does: PREFIX.csv (γ
// and η per case), PREFIX-curves.csv (the mean curves), PREFIX-profiles.csv (E_n(T)), with the
// paper's Table I PREFIX-paper.csv (ours beside it), and PREFIX.json.
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/io/atomic_file.hpp"
#include "granular/study/exponent_table.hpp"
#include "granular/study/paper_comparison.hpp"

namespace granular {

struct ExponentPaths {
  std::string csv, curves, profiles, json;
  std::string paper;  ///< "" without the comparison
  /// Every path, to be checked before the run (io/output_paths.hpp, check_outputs).
  std::vector<std::string> all() const;
};

/// The files under `prefix`, with PREFIX-paper.csv when `paper`.
ExponentPaths exponent_paths(const std::string& prefix, bool paper);

/// Writes the CSVs of `paths` (the comparison from `comparison` when paths.paper is set) under
/// their temporary names, returned to be committed after the JSON.
std::vector<std::unique_ptr<AtomicFile>> write_exponent_files(const ExponentPaths& paths,
                                                              const std::vector<ExponentCell>& cells,
                                                              const std::vector<CellComparison>& comparison);

/// The "cases" entry of the study's JSON, one object per cell: describe(definition), `chain`
/// (its name), `failed_excluded` (the realizations left out), and where the cell has them
/// `exponents` (gamma_site, gamma_centroid, eta: to_json of each report) and `mle_at_T` (X1 at T; the case's own `mle`
/// is whether the tangent map ran).
nlohmann::json describe_cells(const std::vector<ExponentCell>& cells);

/// The "parameters" entry of the JSON beside the cases: the chain kinds and the kicks of `config`
/// (`chains`, `ic`: comma lists, chain_list / kick_list; "none" for no kind), its precompressions
/// F0 [N], the threads as requested (0: every core) and the MPI ranks.
nlohmann::json describe_table_parameters(const ExponentTableConfig& config, int threads);

/// The study's JSON as the exponents tool and granular.exponent_table write it: `parameters`
/// (describe_table_parameters), `cases` (describe_cells), `time_step_rule`, and
/// `resumed_checkpoint` when `resumed` is not null.
nlohmann::json describe_exponent_study(const ExponentTableConfig& config, int threads,
                                       const std::vector<ExponentCell>& cells, const nlohmann::json& step_rule,
                                       const nlohmann::json& resumed);

}  // namespace granular
