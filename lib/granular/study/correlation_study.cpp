#include "granular/study/correlation_study.hpp"

#include <cmath>
#include <string>

#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/error.hpp"
#include "granular/model/correlation.hpp"
#include "granular/model/material.hpp"
#include "granular/number_format.hpp"

namespace granular {

void validate(const CorrelationConfig& c) {
  if (c.beads) validate(*c.beads);
  if (!c.beads && c.disorder == Disorder::homogeneous)
    throw InvalidInput("disorder", " h: a one-type chain has no correlation coefficient");
  if (!c.beads) validate_probability(c.q);
  if (c.n < 2) throw InvalidInput("N", " " + std::to_string(c.n) + ": a chain needs at least 2 beads");
  if (c.n > 100000000) throw InvalidInput("N", " " + std::to_string(c.n) + ": more than 1e8 beads");
  if (c.realizations < 1) throw InvalidInput("realizations", " 0: must be >= 1");
  if (c.max_distance >= c.n)
    throw InvalidInput("max_distance", " " + std::to_string(c.max_distance) + ": must be in [0, N-1]");
}

CorrelationResult correlation_study(const CorrelationConfig& c, const RunOptions& run) {
  validate(c);
  const std::size_t dmax = c.max_distance;
  std::vector<std::vector<double>> rho(c.realizations);
  parallel_realizations(
      c.realizations, run.threads,
      [&](std::size_t r, int) {
        if (!c.beads) {
          rho[r] = cyclic_correlation(realization_configuration(c.disorder, c.q, c.n, c.seed, r), dmax);
          return;
        }
        std::vector<double> mass = realization_radii(*c.beads, c.n, c.seed, r);
        for (double& m : mass) m = sphere_mass(steel, m);
        rho[r] = cyclic_value_correlation(mass, dmax);
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
  if (out.used == 0 && c.beads)
    throw InvalidInput("beads",
                       " " + describe(*c.beads) + ": every realization has one kind of bead only, no correlation");
  if (out.used == 0)
    throw InvalidInput("q", " " + format_number(c.q) + ": every realization has one bead type only, no correlation");
  const double u = static_cast<double>(out.used);
  for (std::size_t d = 0; d <= dmax; ++d) {
    const double mean = sum[d] / u;
    const double var = out.used > 1 ? std::fmax(sum2[d] / u - mean * mean, 0.0) * u / (u - 1) : 0.0;
    out.mean.push_back(mean);
    out.deviation.push_back(std::sqrt(var));
    out.theory.push_back(c.beads ? correlation_theory(*c.beads, d) : correlation_theory(c.disorder, c.q, d));
  }
  return out;
}

}  // namespace granular
