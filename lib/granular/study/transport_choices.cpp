#include "granular/study/transport_choices.hpp"

#include <cmath>

#include "granular/dynamics/integrator.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

double finite_non_negative(double value, const char* name) {
  if (!(value >= 0) || !std::isfinite(value))
    throw InvalidInput(name, " " + format_number(value) + ": must be finite and >= 0");
  return value;
}

}  // namespace

bool take_automatic_integrator(TransportChoices& choices) {
  if (choices.integrator != "auto") return false;
  choices.integrator = "saba2c";
  return true;
}

void fit_within_duration(TransportCase& c) { c.fit = c.fit_end <= c.dynamics.integration.duration * (1 + 1e-12); }

void apply(const TransportChoices& o, TransportCase& c) {
  c.alpha = o.alpha;
  c.match_beta = !o.beta;
  if (o.beta) c.beta = *o.beta;
  const std::size_t n = c.chain.size();
  if (o.site < 0 || o.site > static_cast<long long>(n))
    throw InvalidInput("site", " " + std::to_string(o.site) + ": outside the chain of " + std::to_string(n) +
                                   " beads (1..N, 0 = centre)");
  c.site = o.site == 0 ? (n - 1) / 2 : static_cast<std::size_t>(o.site - 1);
  c.centre = parse_spread_centre(o.centre);
  SpreadingRunConfig& d = c.dynamics;
  d.integration.duration = o.duration;
  d.integration.time_step = o.time_step;
  d.integration.integrator = parse_integrator(o.integrator);
  d.integration.force_law = parse_force_law(o.force_law);
  if (o.samples < 2) throw InvalidInput("samples", " " + std::to_string(o.samples) + ": at least 2");
  d.spread.samples = static_cast<std::size_t>(o.samples);
  d.spread.sampling = parse_sampling(o.sampling);
  d.integration.window.enabled = o.active_window;
  d.integration.window.threshold = finite_non_negative(o.window_threshold, "window_threshold");
  d.integration.integrator.tolerance.max_step = finite_non_negative(o.reference_max_step, "reference_max_step");
  d.spread.max_energy_error = finite_non_negative(o.max_energy_error, "max_energy_error");
  if (o.energy_guard != "stop" && o.energy_guard != "warn")
    throw InvalidInput("energy_guard", " '" + o.energy_guard + "': stop or warn");
  d.spread.stop_on_energy_error = o.energy_guard == "stop";
  if (!(o.fit_begin > 0) || !(o.fit_end > o.fit_begin))
    throw InvalidInput("fit", " " + format_number(o.fit_begin) + ":" + format_number(o.fit_end) +
                                  ": expected start:stop with 0 < start < stop [s]");
  c.fit = true;
  c.fit_begin = o.fit_begin;
  c.fit_end = o.fit_end;
  c.fit_step = o.fit_step;
  c.criterion.kappa = o.kappa;
  c.criterion.t_start = o.t_star;
  if (o.bootstrap < 2) throw InvalidInput("bootstrap", " " + std::to_string(o.bootstrap) + ": at least 2 resamples");
  c.bootstrap.resamples = static_cast<std::size_t>(o.bootstrap);
}

BeyondChoices beyond_choices_of(const SpreadingRunConfig& d) {
  return {.damping_time = d.integration.damping.time,
          .kk_gamma = d.integration.damping.kk_gamma,
          .mle = d.integration.lyapunov.enabled,
          .renormalize = static_cast<long long>(d.integration.lyapunov.renormalize_every),
          .deviation_samples = static_cast<long long>(d.deviation_samples)};
}

void apply(const BeyondChoices& o, SpreadingRunConfig& d) {
  d.integration.damping = {o.damping_time, o.kk_gamma};
  validate(d.integration.damping);
  d.integration.lyapunov.enabled = o.mle;
  if (o.renormalize < 1) throw InvalidInput("renormalize", " " + std::to_string(o.renormalize) + ": at least 1");
  d.integration.lyapunov.renormalize_every = static_cast<std::size_t>(o.renormalize);
  if (o.deviation_samples != 0 && !o.mle) throw InvalidInput("deviation_samples", ": needs mle (the tangent map)");
  if (o.deviation_samples < 0 || o.deviation_samples == 1)
    throw InvalidInput("deviation_samples", " " + std::to_string(o.deviation_samples) + ": 0 (none) or at least 2");
  d.deviation_samples = static_cast<std::size_t>(o.deviation_samples);
}

}  // namespace granular
