#include "granular/klein_gordon/klein_gordon_case.hpp"

#include <cmath>
#include <string>

#include "granular/analysis/power_law_fit.hpp"
#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

// The command line's text form of the window, as the granular tools' --fit: start:stop.
void read_fit(KleinGordonCase& c, const std::string& text) {
  const Interval fit = parse_interval(text, "fit");
  c.fit = {fit.start, fit.stop};
}
std::string write_fit(const KleinGordonCase& c) {
  return c.fit.size() == 2 ? format_number(c.fit[0]) + ":" + format_number(c.fit[1]) : "none";
}

}  // namespace

const ParameterTable<KleinGordonCase>& klein_gordon_parameters() {
  using C = KleinGordonCase;
  using R = KleinGordonRunConfig;
  using K = KleinGordonParameters;
  static const ParameterTable<C> table{
      {"N", path<C>(&C::run, &R::chain, &K::N), "sites, 2 to 10^8, fixed ends"},
      {"W", path<C>(&C::run, &R::chain, &K::W),
       "disorder strength W > 0: bonds of stiffness 1/W, on-site "
       "e_l uniform in [1/2, 3/2]"},
      {"seed", path<C>(&C::run, &R::chain, &K::seed), "random seed of the disorder (and of a block's signs)"},
      {"energy", path<C>(&C::run, &R::energy),
       "single site (`block` 0): its energy E; a block: the energy density h per site (dimensionless, in units "
       "of H)"},
      {"block", path<C>(&C::run, &R::block),
       "0: one site at the centre excited; L >= 1: L central sites, each with energy h and a random sign of its "
       "momentum"},
      {"time_step", path<C>(&C::run, &R::time_step), "SABA2C time step tau [1/omega0], > 0"},
      {"duration", &C::duration, "final time T [1/omega0], >= `time_step`"},
      {"samples", &C::samples, "sample times, log-spaced from `time_step` to T (1 to 10^6; repeated steps dropped)"},
      {"mle", path<C>(&C::run, &R::mle),
       "also the finite-time maximal Lyapunov exponent Lambda(t) [omega0] (tangent map, deviation on the centre "
       "site); on unless `mle`=false"},
      {"energy_map", path<C>(&C::run, &R::energy_map),
       "also the site energies E_l of realization 0 at every sample (samples x N values, at most 2e8)"},
      {"realizations", &C::realizations, "realizations 0 .. count-1 of `seed` (1 to 10^6); more than one: their means"},
      {"threads", &C::threads, "threads over realizations (0 = all cores); results do not depend on it"},
      {"fit",
       &C::fit,
       {read_fit, write_fit},
       "exponent window t0:t1 [1/omega0], 0 < t0 < t1 <= T, at least 3 samples: the least-squares log-log slopes "
       "alpha of m2, alpha_P of P and alpha_Lambda of Lambda (of <log10 Lambda>) over it; none by default",
       false}};
  return table;
}

const char* const klein_gordon_sample_rule =
    "step round(n^(k/(S-1))) for k = 0..S-1, n = round(T/tau), S = samples, repeated steps dropped (S = 1: step n); "
    "t = step tau";

std::vector<std::uint64_t> sample_steps(const KleinGordonCase& c) {
  const auto n = static_cast<std::uint64_t>(std::llround(c.duration / c.run.time_step));
  if (c.samples <= 1) return {n};
  std::vector<std::uint64_t> steps;
  for (long k = 0; k < c.samples; ++k) {  // n^(k/(S−1)): 1 at k = 0, exactly n at k = S − 1
    const double x = k == c.samples - 1
                         ? static_cast<double>(n)
                         : std::pow(static_cast<double>(n), static_cast<double>(k) / static_cast<double>(c.samples - 1));
    const auto step = static_cast<std::uint64_t>(std::llround(x));
    if (steps.empty() || step > steps.back()) steps.push_back(step);
  }
  return steps;
}

KleinGordonRunConfig run_config(const KleinGordonCase& c) {
  KleinGordonRunConfig r = c.run;
  r.sample_steps = sample_steps(c);
  return r;
}

void validate(const KleinGordonCase& c) {
  refuse_unmet_needs(c, klein_gordon_parameters());
  KleinGordonRunConfig run = c.run;
  run.sample_steps = {1};  // its own are made below, from `duration` and `samples`
  validate(run);
  // 10^12 steps bounds the sample steps well inside a double's exact integers and an hour's run by far.
  const double steps = c.duration / c.run.time_step;
  if (!std::isfinite(c.duration) || !(steps >= 1 - 1e-12) || steps > 1e12)
    throw InvalidInput("duration", " " + format_number(c.duration) +
                                       ": must be finite, at least `time_step` and at most 10^12 steps of it");
  if (c.samples < 1 || c.samples > 1000000)
    throw InvalidInput("samples", " " + std::to_string(c.samples) + ": must be in [1, 10^6]");
  if (c.run.energy_map) validate(run_config(c));  // the map's size: samples taken × N
  // Every realization's curves are kept (the means are summed in index order afterwards).
  if (c.realizations < 1 || c.realizations > 1000000)
    throw InvalidInput("realizations", " " + std::to_string(c.realizations) + ": must be in [1, 10^6]");
  if (c.threads < 0 || c.threads > 4096)
    throw InvalidInput("threads", " " + std::to_string(c.threads) + ": 0 (every core) to 4096");
  if (c.fit.empty()) return;
  if (c.fit.size() != 2)
    throw InvalidInput("fit", ": expected a window (t0, t1), " + std::to_string(c.fit.size()) + " values given");
  const double t0 = c.fit[0], t1 = c.fit[1];
  const std::string window = " " + format_number(t0) + ":" + format_number(t1);
  if (!(t0 > 0 && t0 < t1 && t1 <= c.duration * (1 + 1e-12)))
    throw InvalidInput("fit", window + ": must satisfy 0 < t0 < t1 <= T = " + format_number(c.duration));
  std::vector<double> times;  // as the run reaches them: step τ
  for (const std::uint64_t step : sample_steps(c)) times.push_back(static_cast<double>(step) * c.run.time_step);
  const std::size_t inside = samples_inside(times, t0, t1);
  if (inside < 3)
    throw InvalidInput("fit", window + ": holds " + std::to_string(inside) +
                                  " sample(s), need at least 3 (a wider window or more `samples`)");
}

}  // namespace granular
