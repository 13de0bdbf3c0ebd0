#include "granular/study/correlation_study.hpp"

#include <cmath>
#include <string>

#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/error.hpp"
#include "granular/model/correlation.hpp"
#include "granular/model/material.hpp"
#include "granular/number_format.hpp"

namespace granular {

const ParameterTable<CorrelationConfig>& correlation_parameters() {
  using C = CorrelationConfig;
  static const ParameterTable<C> table{{"realizations", &C::realizations, "chains averaged"},
                                       {"max_distance", &C::max_distance,
                                        "largest shift d (< N; default capped at N-1)"}};
  return table;
}

ChainChoices correlation_chain_defaults() { return chain_choices(CorrelationConfig{}.chain); }

void set_chain(CorrelationConfig& c, const ChainChoices& beads) {
  set_study_draw(c.chain, beads);
  if (auto distribution = bead_distribution(chain_kind_choices(beads))) c.chain.source = *distribution;
}

void validate(const CorrelationConfig& c) {
  const ChainRecipe& chain = c.chain;
  if (!chain.drawn()) throw InvalidInput("chain", ": an ensemble draws its chains; not a given chain");
  if (const auto* draw = chain.as<TwoTypeDraw>(); draw && draw->disorder == Disorder::homogeneous)
    throw InvalidInput("disorder", " h: a one-type chain has no correlation coefficient");
  validate(chain);
  if (c.realizations < 1) throw InvalidInput("realizations", " 0: must be >= 1");
  if (c.max_distance >= chain.N)
    throw InvalidInput("max_distance", " " + std::to_string(c.max_distance) + ": must be in [0, N-1]");
}

CorrelationResult correlation_study(const CorrelationConfig& c, const RunOptions& run) {
  validate(c);
  const std::size_t dmax = c.max_distance;
  std::vector<std::vector<double>> rho(c.realizations);
  parallel_realizations(
      c.realizations, run.threads,
      [&](std::size_t r, int) {
        if (!c.chain.as<BeadDistribution>()) {
          rho[r] = cyclic_correlation(c.chain.types(r), dmax);
          return;
        }
        rho[r] = cyclic_value_correlation(c.chain.chain(r).mass, dmax);
      },
      run.progress);
  // Chains of one type only (possible at small N or q near 0 or 1) have no coefficient: skipped.
  CorrelationResult out;
  std::vector<double> sum(dmax + 1, 0.0), sum2(dmax + 1, 0.0);
  for (const auto& row : rho) {  // realization order: thread-count independent
    if (std::isnan(row[0])) continue;
    ++out.used;
    for (std::size_t d = 0; d <= dmax; ++d) {
      sum[d] += row[d];
      sum2[d] += row[d] * row[d];
    }
  }
  const auto* beads = c.chain.as<BeadDistribution>();
  if (out.used == 0 && beads)
    throw InvalidInput("beads",
                       " " + describe(*beads) + ": every realization has one kind of bead only, no correlation");
  if (out.used == 0)
    throw InvalidInput("q", " " + format_number(c.chain.draw().q) +
                                ": every realization has one bead type only, no correlation");
  const double u = static_cast<double>(out.used);
  for (std::size_t d = 0; d <= dmax; ++d) {
    const double mean = sum[d] / u;
    const double var = out.used > 1 ? std::fmax(sum2[d] / u - mean * mean, 0.0) * u / (u - 1) : 0.0;
    out.mean.push_back(mean);
    out.deviation.push_back(std::sqrt(var));
    out.theory.push_back(beads ? correlation_theory(*beads, d)
                               : correlation_theory(c.chain.draw().disorder, c.chain.draw().q, d));
  }
  return out;
}

}  // namespace granular
