#pragma once
// Our exponent table beside the paper's Table I (γ; Martínez, Kevrekidis & Porter, PRE 93,
// 022902 (2016)), with z-scores. A report to read, not a target: nothing in the study is tuned
// towards it (docs/physics.md, "Nonlinear dynamics").
//
// For each cell and each m̃2 centre, Δ = ours − paper (the values each table shows: a fit, or the
// mean L_d where starred) and two z-scores:
//   z_window = Δ / sqrt(w_ours² + w_paper² + p²)             (the paper's ±: sub-window spreads only)
//   z        = Δ / sqrt(w_ours² + w_paper² + p² + r_ours² + r_paper²)
// where r is the realization error: ours from the bootstrap, the paper's estimated as ours scaled
// to its 500 realizations, r_paper = r_ours sqrt(R_ours / 500) (same ensemble, same estimator: the
// paper's average carries the same realization noise, which its ± leaves out); and p = 0.0005/√3,
// the paper's printing to three decimals (a uniform ±0.0005), which alone is left for the
// homogeneous chains (no ± printed, one deterministic run on our side).
#include <iosfwd>
#include <string>
#include <vector>

#include "granular/study/exponent_table.hpp"

namespace granular {

struct PaperCell {
  Kick kick = Kick::displacement;
  double precompression = 0;  ///< F0 [N]
  Disorder disorder = Disorder::homogeneous;
  double gamma = 0;
  double error = 0;      ///< the paper's ± (0 where it prints none: the homogeneous chains)
  bool starred = false;  ///< the paper's (*): the value is a mean L_d
};

/// Reads the table (CSV `ic,F0_N,disorder,gamma,err,star`, '#' comments), e.g.
/// data/paper_table1_gamma.csv. Throws IoError if unreadable, InvalidInput on a malformed row.
std::vector<PaperCell> read_paper_table(const std::string& path);

/// Realizations per case in the paper.
inline constexpr double paper_realizations = 500;
/// Standard deviation of the paper's rounding to three decimals, 0.0005/√3.
inline constexpr double paper_rounding = 0.0005 / 1.7320508075688772;

struct CentreComparison {
  double value = 0, window_error = 0, realization_error = 0;
  bool starred = false;
  double z_window = 0, z = 0;  ///< as above; ±inf when every error is 0 and Δ is not
};

struct CellComparison {
  PaperCell paper;
  std::size_t realizations = 0;
  CentreComparison site, centroid;
};

/// The paper's cells that our run has (same kick, F0 and chain), in the paper's order.
std::vector<CellComparison> compare_with_paper(const std::vector<ExponentCell>& cells,
                                               const std::vector<PaperCell>& paper);

/// The side-by-side Markdown table and a count of the cells within 2 and 3 of each z.
std::string markdown_comparison(const std::vector<CellComparison>& rows);
void write_comparison_csv(std::ostream& out, const std::vector<CellComparison>& rows);

}  // namespace granular
