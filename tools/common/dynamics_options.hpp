#pragma once
// The options of a kicked-chain run, shared by `spreading` and `exponents` so that the same case
// gives the same numbers from both: one default for every physical choice (the paper's: α = 1e-7 m,
// β = 8e-3 m/s, the kick at the centre bead, m̃2 about the excited site, fits on 4–10 ms sampled
// every 10 µs, t* = 4 ms, κ = 0.1), one --fit and one --beta parser. The library's messages name
// parameters (`fit_step`, `t_star`); tool::run tells them as these flags (`--fit-step`, `--t-star`).
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "beyond_options.hpp"
#include "chain_options.hpp"
#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/number_format.hpp"
#include "granular/study/case_settling.hpp"
#include "granular/study/time_step_rule.hpp"
#include "granular/study/transport_choices.hpp"
#include "granular/study/transport_study.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// The options bind straight into the library's choices, except the three whose words only a
/// command line has: --beta (a number or 'match'), --fit (start:stop), --active-window (on|off).
struct DynamicsOptions {
  TransportChoices choices;
  std::string beta = "8e-3", fit = "4e-3:1e-2", active_window = "on";
  BeyondOptions beyond;  ///< damping (here) and the tangent map (spreading adds its flags)
};

inline void add_dynamics_options(CLI::App& app, DynamicsOptions& o) {
  TransportChoices& c = o.choices;
  add_option(app, "--alpha", c.alpha, "displacement kick [m] (also what --beta match matches)");
  add_option(app, "--beta", o.beta,
             "velocity kick [m/s] (the paper's 8e-3 for every F0), or 'match': the energy of --alpha on each chain");
  add_option(app, "--site", c.site, "kicked bead n0, 1..N (0 = the centre, (N+1)/2)");
  add_option(app, "--centre", c.centre,
             "m2 about the kicked 'site' (the paper's n_c) or the energy 'centroid'; both are written");
  add_option(app, "--T", c.duration, "duration [s], a whole number of --dt");
  add_option(app, "--dt", c.time_step,
             "time step tau [s]; must meet tau <= h*/omega_max (docs/physics.md, 'Time step'): a larger one is "
             "refused, naming the largest stable tau; by default 1e-6, or 1e-6/k (smallest integer k) where 1e-6 "
             "is past a sixth of that limit");
  add_option(app, "--integrator", c.integrator,
             "saba2c | saba2 | aba864 | srkn14a | reference (Odeint RKF78) | auto: the cheapest scheme and step "
             "keeping the energy error at SABA2C's at 1e-6 s: SRKN14a at 5e-6 s where no contact can open, else "
             "SABA2C (docs/physics.md, 'Chain length for long times'); no --dt with it");
  add_option(app, "--force-law", c.force_law, "hertz | fpu | linear");
  add_option(app, "--samples", c.samples, "log-spaced sample times (tau..T) outside the fit window");
  add_option(app, "--sampling", c.sampling, "log (tau..T) | uniform (0..T) for those samples");
  add_option(app, "--fit", o.fit, "fit window start:stop [s] of gamma (m2 ~ t^gamma) and eta (P^-1 ~ t^-eta)");
  add_option(app, "--fit-step", c.fit_step, "spacing of the samples inside the fit window [s], a multiple of --dt");
  add_option(app, "--t-star", c.t_star, "t*: from here on, |L_d - gamma| >= --kappa means 'not a power law' [s]");
  add_option(app, "--kappa", c.kappa, "largest |L_d - gamma| of a power law after --t-star");
  add_option(app, "--bootstrap", c.bootstrap, "resamples of the realization bootstrap of gamma and eta");
  add_option(app, "--active-window", o.active_window, "on | off: integrate only where the wave has arrived");
  add_option(app, "--window-threshold", c.window_threshold, "relative kinetic energy that grows the window");
  add_option(app, "--reference-max-step", c.reference_max_step, "largest step of --integrator reference [s], 0 = none");
  add_option(app, "--max-energy-error", c.max_energy_error,
             "guard: relative energy error that stops (or is reported), 0 = off");
  add_option(app, "--energy-guard", c.energy_guard, "stop | warn: what passing --max-energy-error does");
  add_damping_options(app, o.beyond);
}

/// Fills `c` from the options: granular::apply(TransportChoices) once the three command-line
/// words are read. Needs c.n (for --site).
inline void apply(const DynamicsOptions& o, TransportCase& c) {
  TransportChoices choices = o.choices;
  if (choices.integrator == "auto") choices.integrator = "saba2c";  // settled with the step (settle_time_step)
  if (o.beta != "match") choices.beta = parse_number_list(o.beta, "--beta", 0, 1).at(0);
  else choices.beta.reset();
  if (o.active_window != "on" && o.active_window != "off")
    throw InvalidInput("--active-window '" + o.active_window + "': on or off");
  choices.active_window = o.active_window == "on";
  const Interval fit = parse_interval(o.fit, "--fit");
  choices.fit_begin = fit.start;
  choices.fit_end = fit.stop;
  granular::apply(choices, c);
  apply(o.beyond, c.dynamics);
}

/// granular::validate_and_settle (case_settling.hpp): the cases validated with the errors in the
/// order a user can act on them (a --dt past the stability limit before a --fit-step judged on
/// it), the time step, and with `--integrator auto` the scheme first (SRKN14a at 5 µs where no
/// contact can open and it is cheaper, else SABA2C); then the --T warning, after the errors.
inline nlohmann::json validate_and_settle(std::vector<TransportCase>& cases, const DynamicsOptions& o, bool dt_given) {
  std::string warning;
  nlohmann::json rule = granular::validate_and_settle(cases, o.choices.integrator == "auto", dt_given, "--T", warning);
  warn({warning});
  return rule;
}

/// The same for one case.
inline nlohmann::json validate_and_settle(TransportCase& c, const DynamicsOptions& o, bool dt_given) {
  std::string warning;
  nlohmann::json rule = granular::validate_and_settle(c, o.choices.integrator == "auto", dt_given, "--T", warning);
  warn({warning});
  return rule;
}

}  // namespace granular::tool
