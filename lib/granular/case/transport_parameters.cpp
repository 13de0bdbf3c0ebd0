#include "granular/case/transport_parameters.hpp"

#include <algorithm>

#include "granular/dynamics/integrator.hpp"
#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

using C = TransportCase;
using D = SpreadingRunConfig;

// Where the rows' values live in the case.
constexpr auto integration = &D::integration;
const auto duration = path<C>(&C::dynamics, integration, &IntegrationConfig::duration);
const auto samples = path<C>(&C::dynamics, &D::spread, &EnergySpreadObserver::Settings::samples);

// The command line's text forms: a velocity or 'match', a window start:stop, on|off, the enums' words.
void read_beta(C& c, const std::string& text) {
  if (text == "match") c.beta.reset();
  else c.beta = parse_number_list(text, "beta", 0, 1).at(0);
}
std::string write_beta(const C& c) { return c.beta ? format_number(*c.beta) : "match"; }
void read_fit(C& c, const std::string& text) {
  const Interval fit = parse_interval(text, "fit");
  c.fit_begin = fit.start, c.fit_end = fit.stop;
}
std::string write_fit(const C& c) { return format_number(c.fit_begin) + ":" + format_number(c.fit_end); }
void read_on_off(C& c, const std::string& text) {
  if (text != "on" && text != "off") throw InvalidInput("active_window", " '" + text + "': on or off");
  c.dynamics.integration.window.enabled = text == "on";
}
std::string write_on_off(const C& c) { return c.dynamics.integration.window.enabled ? "on" : "off"; }
void read_centre(C& c, const std::string& word) { c.centre = parse_spread_centre(word); }
std::string write_centre(const C& c) { return to_string(c.centre); }
/// "auto" stands for SABA2C until settled (case_settling.hpp); the reference's tolerance is kept.
void read_integrator(C& c, const std::string& word) {
  Integrator& integrator = c.dynamics.integration.integrator;
  const ReferenceTolerance tolerance = integrator.tolerance;
  c.automatic_integrator = word == "auto";
  integrator = c.automatic_integrator ? Integrator() : parse_integrator(word);
  integrator.tolerance = tolerance;
}
std::string write_integrator(const C& c) {
  return c.automatic_integrator ? "auto" : c.dynamics.integration.integrator.name();
}
void read_force_law(C& c, const std::string& word) { c.dynamics.integration.force_law = parse_force_law(word); }
std::string write_force_law(const C& c) { return to_string(c.dynamics.integration.force_law); }
void read_sampling(C& c, const std::string& word) { c.dynamics.spread.sampling = parse_sampling(word); }
std::string write_sampling(const C& c) { return to_string(c.dynamics.spread.sampling); }
void read_guard(C& c, const std::string& word) {
  if (word != "stop" && word != "warn") throw InvalidInput("energy_guard", " '" + word + "': stop or warn");
  c.dynamics.spread.stop_on_energy_error = word == "stop";
}
std::string write_guard(const C& c) { return c.dynamics.spread.stop_on_energy_error ? "stop" : "warn"; }
void read_kick(C& c, const std::string& word) { c.kick = parse_kick(word); }
std::string write_kick(const C& c) { return to_string(c.kick); }

}  // namespace

const ParameterTable<TransportCase>& transport_parameters() {
  using P = Parameter<C>;
  using Lyapunov = LyapunovConfig;
  static const ParameterTable<C> table{
      {"alpha", &C::alpha, "displacement kick [m] (also what a matched `beta` matches)"},
      {"beta",
       &C::beta,
       {read_beta, write_beta},
       "velocity kick [m/s] (the paper's 8e-3 for every F0), or 'match': the energy of `alpha` on each chain"},
      {"site", &C::site, "kicked bead n0, 1..N (0 = the centre, (N+1)/2)"},
      P{"centre",
        {},
        {read_centre, write_centre},
        "m2 about the kicked 'site' (the paper's n_c) or the energy 'centroid'; both are written, this one gives "
        "gamma"}
          .as_word(),
      {"duration", duration, "duration T [s], a whole number of `time_step`"},
      {"time_step", &C::time_step,
       "time step tau [s]; must meet tau <= h*/omega_max (docs/physics.md, 'Time step'): a larger one is refused, "
       "naming the largest stable tau; by default 1e-6, or 1e-6/k (smallest integer k) where 1e-6 is past a sixth "
       "of that limit; the rule and its numbers are in the JSON (time_step_rule)",
       false},
      P{"integrator",
        {},
        {read_integrator, write_integrator},
        "saba2c | saba2 | aba864 | srkn14a | reference (Odeint RKF78) | auto: the cheapest scheme and step keeping "
        "the energy error at SABA2C's at 1e-6 s: SRKN14a at 5e-6 s where no contact can open, else SABA2C "
        "(docs/physics.md, 'Chain length for long times'); no `time_step` with it"}
          .as_word(),
      P{"force_law", {}, {read_force_law, write_force_law}, "hertz | fpu | linear"}.as_word(),
      {"samples", samples, "log-spaced sample times (tau..T) outside the fit window"},
      P{"sampling", {}, {read_sampling, write_sampling}, "log (tau..T) | uniform (0..T) for those samples"}.as_word(),
      P{"fit", {}, {read_fit, write_fit}, "fit window start:stop [s] of gamma (m2 ~ t^gamma) and eta (P^-1 ~ t^-eta)"}
          .shorthand(),
      {"fit_begin", &C::fit_begin, "start of the fit window [s]"},
      {"fit_end", &C::fit_end, "end of the fit window [s]"},
      {"fit_step", &C::fit_step, "spacing of the samples inside the fit window [s], a multiple of `time_step`"},
      {"t_star", path<C>(&C::criterion, &PowerLawCriterion::t_start),
       "t*: from here on, |L_d - gamma| >= `kappa` means 'not a power law' [s]"},
      P{"kappa", path<C>(&C::criterion, &PowerLawCriterion::kappa),
        "largest |L_d - gamma| of a power law after `t_star`"}
          .positive(),
      {"bootstrap", path<C>(&C::bootstrap, &BootstrapConfig::resamples),
       "resamples of the realization bootstrap of gamma and eta"},
      {"bootstrap_seed", path<C>(&C::bootstrap, &BootstrapConfig::seed),
       "key of the bootstrap's resampling draw (apart from the chains' seed): another key redraws the resamples, "
       "so the realization errors' own scatter can be seen"},
      {"active_window",
       path<C>(&C::dynamics, integration, &IntegrationConfig::window, &ActiveWindow::enabled),
       {read_on_off, write_on_off},
       "integrate only where the wave has arrived, on or off (results equal the whole chain's)"},
      P{"window_threshold", path<C>(&C::dynamics, integration, &IntegrationConfig::window, &ActiveWindow::threshold),
        "relative kinetic energy that grows the window"}
          .needing("active_window")
          .at_least(0),
      P{"reference_max_step",
        path<C>(&C::dynamics, integration, &IntegrationConfig::integrator, &Integrator::tolerance,
                &ReferenceTolerance::max_step),
        "largest step of the reference integrator [s], 0 = none"}
          .needing("integrator", {"reference"})
          .at_least(0),
      P{"max_energy_error", path<C>(&C::dynamics, &D::spread, &EnergySpreadObserver::Settings::max_energy_error),
        "guard: relative energy error that stops (or is reported), 0 = off"}
          .at_least(0),
      P{"energy_guard", {}, {read_guard, write_guard}, "stop | warn: what passing `max_energy_error` does"}
          .as_word()
          .needing("max_energy_error"),
      {"damping_time", path<C>(&C::dynamics, integration, &IntegrationConfig::damping, &Damping::time),
       "on-site viscous damping time tau_d [s] of -(m/tau_d) du/dt; 0 = none"},
      {"kk_gamma", path<C>(&C::dynamics, integration, &IntegrationConfig::damping, &Damping::kk_gamma),
       "Kuwabara-Kono contact damping gamma_KK [s]: bond force A[d]^{3/2} + gamma A [d]^{1/2} dd/dt, not clipped at "
       "zero (a damped contact can pull while it unloads); 0 = none"},
      {"mle", path<C>(&C::dynamics, integration, &IntegrationConfig::lyapunov, &Lyapunov::enabled),
       "maximal Lyapunov exponent X1(t) [1/s] by the tangent map of the same scheme (conservative runs: not with "
       "damping or the reference integrator)"},
      P{"renormalize", path<C>(&C::dynamics, integration, &IntegrationConfig::lyapunov, &Lyapunov::renormalize_every),
        "steps between renormalizations of the deviation vector"}
          .needing("mle"),
      P{"norm_time_unit", path<C>(&C::dynamics, integration, &IntegrationConfig::lyapunov, &Lyapunov::time_unit),
        "t_unit [s] of the deviation vectors' norm |(du, t_unit dv)| (with `mle`): X1(t) at finite t depends on it, "
        "its limit does not"}
          .needing("mle")
          .positive(),
      P{"deviation_samples", path<C>(&C::dynamics, &D::deviation_samples),
        "uniform times (0..T) of the deviation vector's distribution along the chain (with `mle`)"}
          .needing("mle"),
      P{"lyapunov_vectors", path<C>(&C::dynamics, &D::lyapunov_vectors),
        "k deviation vectors of a Lyapunov spectrum on the same orbit, 1..2N (0 = none; one realization): "
        "lambda_1..lambda_k(t) [1/s], GALI_2..GALI_k(t) and SALI(t) at the sample times, QR every `renormalize` "
        "steps (with `mle`: the same tangent map and its rules)"}
          .needing("mle"),
      P{"covariant_vectors", path<C>(&C::dynamics, &D::covariant_vectors),
        "k covariant Lyapunov vectors (Ginelli's method) on the same orbit, 1..2N (0 = none; one realization): at "
        "the sample times from `covariant_transient` to T, QR every `renormalize` steps (with `mle`)"}
          .needing("mle"),
      P{"covariant_transient", path<C>(&C::dynamics, &D::covariant_transient),
        "forward and backward transient of the covariant vectors [s]: their samples start there, the backward "
        "phase that long after T (default T/2)"}
          .needing("covariant_vectors")};
  return table;
}

const ParameterTable<ModeKick>& mode_kick_parameters() {
  static const ParameterTable<ModeKick> table{
      {"mode", &ModeKick::mode, "a mode kick: the linear mode number K, 1..N by increasing frequency", false},
      Parameter<ModeKick>{"near_khz", &ModeKick::near_khz, "a mode kick: the linear mode nearest this frequency [kHz]",
                          false}
          .formerly("mode_khz"),
      {"energy", &ModeKick::energy,
       "a mode kick: total energy of the initial state [J] (without it `alpha` is the largest |u_n|)", false}};
  return table;
}

const ParameterTable<TransportCase>& kicked_case_parameters() {
  static const ParameterTable<C> table{
      Parameter<C>{"ic",
                   {},
                   {read_kick, write_kick},
                   "initial condition: displacement | velocity | mode (a linear mode: `mode`, `near`)"}
          .as_word(),
      {"realizations", &C::realizations, "realizations to average (ensemble means and exponents; >= 1)"}};
  return table;
}

const ParameterTable<TransportCase>& case_parameters() {
  static const ParameterTable<C> table = [] {
    ParameterTable<C> all = kicked_case_parameters();
    const ParameterTable<C>& run = transport_parameters();
    const ParameterTable<C> mode = nested_rows(mode_kick_parameters(), &C::mode);
    all.insert(all.end(), run.begin(), run.end());
    all.insert(all.end(), mode.begin(), mode.end());
    return all;
  }();
  return table;
}

void refuse_mode_without_mode_kick(const ModeKick& kick, const std::vector<Kick>& kicks) {
  if (chosen(kick) && std::find(kicks.begin(), kicks.end(), Kick::mode) == kicks.end())
    throw InvalidInput("`mode`/`near_khz`/`energy`: only with `ic` mode");
}

void fit_within_duration(TransportCase& c) { c.fit = c.fit_end <= c.dynamics.integration.duration * (1 + 1e-12); }

}  // namespace granular
