#include "granular/study/ipr_map_estimate.hpp"

#include <algorithm>
#include <cmath>

#include "granular/linear/dynamical_matrix.hpp"
#include "granular/number_format.hpp"

namespace granular {

IprMapEstimate estimate_ipr_map(const IprMapConfig& c, int threads) {
  IprMapEstimate e;
  e.threads = std::max(threads, 1);
  const bool one_cell = !c.chain.typed();  // a bead distribution or a quasiperiodic chain
  e.chains = (one_cell ? 1 : c.q_values.size() * c.xi_values.size()) * c.realizations;
  if (c.selection.kind != ModeSelection::Kind::all || c.chain.N < 4000) return e;  // short: not timed
  ChainRecipe first = c.chain;
  if (!one_cell) first.draw().q = c.q_values.front(), first.draw().xi = c.xi_values.front();
  e.chain = estimate_every_mode_solve(dynamical_matrix(first.chain(0)), c.spectrum, c.selection);
  const auto rounds =
      static_cast<double>((e.chains + static_cast<std::size_t>(e.threads) - 1) / static_cast<std::size_t>(e.threads));
  e.seconds = e.chain.seconds * rounds;
  return e;
}

std::string describe(const IprMapEstimate& e) {
  const auto scale = [](double s) {
    return s < 120    ? format_number(std::round(s)) + " s"
           : s < 7200 ? format_number(std::round(s / 6) / 10) + " min"
                      : format_number(std::round(s / 360) / 10) + " h";
  };
  return std::to_string(e.chains) + " chain" + (e.chains == 1 ? "" : "s") + " of " + std::to_string(e.chain.beads) +
         " beads, every mode: about " + scale(e.seconds) + " on " + std::to_string(e.threads) + " thread" +
         (e.threads == 1 ? "" : "s") + " (one chain: about " + scale(e.chain.seconds) + "; " +
         std::to_string(e.chain.sample_beads) + " beads took " +
         format_number(std::round(e.chain.sample_seconds * 1e3) / 1e3) + " s, time grows as N^" +
         format_number(std::round(e.chain.power * 10) / 10) + " here); progress counts chains";
}

}  // namespace granular
