#include "granular/study/transport_choices.hpp"

#include <algorithm>
#include <cmath>

#include "granular/dynamics/integrator.hpp"
#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

double finite_non_negative(double value, const char* name) {
  if (!(value >= 0) || !std::isfinite(value))
    throw InvalidInput(name, " " + format_number(value) + ": must be finite and >= 0");
  return value;
}

// The command line's text forms: a velocity or 'match', a window start:stop, on|off.
void read_beta(TransportChoices& o, const std::string& text) {
  if (text == "match") o.beta.reset();
  else o.beta = parse_number_list(text, "beta", 0, 1).at(0);
}
std::string write_beta(const TransportChoices& o) { return o.beta ? format_number(*o.beta) : "match"; }
void read_fit(TransportChoices& o, const std::string& text) {
  const Interval fit = parse_interval(text, "fit");
  o.fit_begin = fit.start, o.fit_end = fit.stop;
}
std::string write_fit(const TransportChoices& o) { return format_number(o.fit_begin) + ":" + format_number(o.fit_end); }
void read_on_off(TransportChoices& o, const std::string& text) {
  if (text != "on" && text != "off") throw InvalidInput("active_window", " '" + text + "': on or off");
  o.active_window = text == "on";
}
std::string write_on_off(const TransportChoices& o) { return o.active_window ? "on" : "off"; }

}  // namespace

const ParameterTable<TransportChoices>& transport_parameters() {
  using O = TransportChoices;
  using P = Parameter<O>;
  static const ParameterTable<O> table{
      {"alpha", &O::alpha, "displacement kick [m] (also what a matched `beta` matches)"},
      {"beta",
       &O::beta,
       {read_beta, write_beta},
       "velocity kick [m/s] (the paper's 8e-3 for every F0), or 'match': the energy of `alpha` on each chain"},
      {"site", &O::site, "kicked bead n0, 1..N (0 = the centre, (N+1)/2)"},
      {"centre", &O::centre,
       "m2 about the kicked 'site' (the paper's n_c) or the energy 'centroid'; both are written, this one gives "
       "gamma"},
      {"duration", &O::duration, "duration T [s], a whole number of `time_step`"},
      {"time_step", &O::time_step,
       "time step tau [s]; must meet tau <= h*/omega_max (docs/physics.md, 'Time step'): a larger one is refused, "
       "naming the largest stable tau; by default 1e-6, or 1e-6/k (smallest integer k) where 1e-6 is past a sixth "
       "of that limit; the rule and its numbers are in the JSON (time_step_rule)",
       false},
      {"integrator", &O::integrator,
       "saba2c | saba2 | aba864 | srkn14a | reference (Odeint RKF78) | auto: the cheapest scheme and step keeping "
       "the energy error at SABA2C's at 1e-6 s: SRKN14a at 5e-6 s where no contact can open, else SABA2C "
       "(docs/physics.md, 'Chain length for long times'); no `time_step` with it"},
      {"force_law", &O::force_law, "hertz | fpu | linear"},
      {"samples", &O::samples, "log-spaced sample times (tau..T) outside the fit window"},
      {"sampling", &O::sampling, "log (tau..T) | uniform (0..T) for those samples"},
      {"fit", {}, {read_fit, write_fit}, "fit window start:stop [s] of gamma (m2 ~ t^gamma) and eta (P^-1 ~ t^-eta)"},
      {"fit_begin", &O::fit_begin, "start of the fit window [s]"},
      {"fit_end", &O::fit_end, "end of the fit window [s]"},
      {"fit_step", &O::fit_step, "spacing of the samples inside the fit window [s], a multiple of `time_step`"},
      {"t_star", &O::t_star, "t*: from here on, |L_d - gamma| >= `kappa` means 'not a power law' [s]"},
      {"kappa", &O::kappa, "largest |L_d - gamma| of a power law after `t_star`"},
      {"bootstrap", &O::bootstrap, "resamples of the realization bootstrap of gamma and eta"},
      {"active_window",
       &O::active_window,
       {read_on_off, write_on_off},
       "on | off: integrate only where the wave has arrived (results equal the whole chain's)"},
      P{"window_threshold", &O::window_threshold, "relative kinetic energy that grows the window"}.needing(
          "active_window"),
      P{"reference_max_step", &O::reference_max_step, "largest step of the reference integrator [s], 0 = none"}.needing(
          "integrator", {"reference"}),
      {"max_energy_error", &O::max_energy_error, "guard: relative energy error that stops (or is reported), 0 = off"},
      P{"energy_guard", &O::energy_guard, "stop | warn: what passing `max_energy_error` does"}.needing(
          "max_energy_error")};
  return table;
}

const ParameterTable<BeyondChoices>& beyond_parameters() {
  using O = BeyondChoices;
  using P = Parameter<O>;
  static const ParameterTable<O> table{
      {"damping_time", &O::damping_time, "on-site viscous damping time tau_d [s] of -(m/tau_d) du/dt; 0 = none"},
      {"kk_gamma", &O::kk_gamma,
       "Kuwabara-Kono contact damping gamma_KK [s]: bond force A[d]^{3/2} + gamma A [d]^{1/2} dd/dt, not clipped at "
       "zero (a damped contact can pull while it unloads); 0 = none"},
      {"mle", &O::mle,
       "maximal Lyapunov exponent X1(t) [1/s] by the tangent map of the same scheme (conservative runs: not with "
       "damping or the reference integrator)"},
      P{"renormalize", &O::renormalize, "steps between renormalizations of the deviation vector"}.needing("mle"),
      P{"deviation_samples", &O::deviation_samples,
        "uniform times (0..T) of the deviation vector's distribution along the chain (with `mle`)"}
          .needing("mle")};
  return table;
}

const ParameterTable<ModeKick>& mode_kick_parameters() {
  static const ParameterTable<ModeKick> table{
      {"mode", &ModeKick::mode, "a mode kick: the linear mode number K, 1..N by increasing frequency", false},
      {"mode_khz", &ModeKick::near_khz, "a mode kick: the linear mode nearest this frequency [kHz]", false},
      {"energy", &ModeKick::energy,
       "a mode kick: total energy of the initial state [J] (without it `alpha` is the largest |u_n|)", false}};
  return table;
}

void apply(const ModeKick& kick, const std::vector<Kick>& kicks, TransportCase& c) {
  if (chosen(kick) && std::find(kicks.begin(), kicks.end(), Kick::mode) == kicks.end())
    throw InvalidInput("`mode`/`mode_khz`/`energy`: only with `ic` mode");
  c.mode = kick;
}

void apply(const TransportChoices& choices, const BeyondChoices& beyond, TransportCase& c) {
  apply(choices, c);
  apply(beyond, c.dynamics);
}

void fit_within_duration(TransportCase& c) { c.fit = c.fit_end <= c.dynamics.integration.duration * (1 + 1e-12); }

void apply(const TransportChoices& o, TransportCase& c) {
  refuse_unmet_needs(o, transport_parameters());  // `energy_guard` with no guard is refused, not ignored
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
  c.time_step = o.time_step;
  if (o.time_step) d.integration.time_step = *o.time_step;  // else the preferred τ the rule starts from
  c.automatic_integrator = o.integrator == "auto";
  d.integration.integrator = c.automatic_integrator ? Integrator() : parse_integrator(o.integrator);  // SABA2C
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
  refuse_unmet_needs(o, beyond_parameters());  // `renormalize`, `deviation_samples`: the tangent map's
  d.integration.damping = {o.damping_time, o.kk_gamma};
  validate(d.integration.damping);
  d.integration.lyapunov.enabled = o.mle;
  if (o.renormalize < 1) throw InvalidInput("renormalize", " " + std::to_string(o.renormalize) + ": at least 1");
  d.integration.lyapunov.renormalize_every = static_cast<std::size_t>(o.renormalize);
  if (o.deviation_samples < 0 || o.deviation_samples == 1)
    throw InvalidInput("deviation_samples", " " + std::to_string(o.deviation_samples) + ": 0 (none) or at least 2");
  d.deviation_samples = static_cast<std::size_t>(o.deviation_samples);
}

}  // namespace granular
