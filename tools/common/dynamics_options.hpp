#pragma once
// The options of a kicked-chain run, shared by `spreading` and `exponents` so that the same case
// gives the same numbers from both: one default for every physical choice (the paper's: α = 1e-7 m,
// β = 8e-3 m/s, the kick at the centre bead, m̃2 about the excited site, fits on 4–10 ms sampled
// every 10 µs, t* = 4 ms, κ = 0.1). The library's messages name
// parameters (`fit_step`, `t_star`); tool::run tells them as these flags (`--fit-step`, `--t-star`).
// Beyond the paper (docs/physics.md, "Nonlinear dynamics"): dissipation (--damping-time, --kk-gamma)
// and the maximal Lyapunov exponent by the tangent map (`spreading --mle`, `exponents --mle`).
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "chain_options.hpp"
#include "granular/error.hpp"
#include "granular/study/case_settling.hpp"
#include "granular/study/spreading_run.hpp"
#include "granular/study/time_step_rule.hpp"
#include "granular/study/transport_choices.hpp"
#include "granular/study/transport_study.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// The library's choices, with the file only the tool writes: --deviation FILE turns on --deviation-samples.
struct BeyondOptions : BeyondChoices {
  BeyondOptions() { deviation_samples = 20; }
  std::string deviation;  ///< CSV of the deviation-vector distribution; empty = none
};

/// --mle (its help ending in `output`: what the tool writes of it) and --renormalize.
inline void add_mle_options(CLI::App& app, BeyondOptions& o, const std::string& output) {
  auto options = add_parameters<BeyondChoices>(app, o, beyond_parameters(),
                                               {.except = {"damping_time", "kk_gamma", "deviation_samples"}});
  options["mle"]->description(options["mle"]->get_description() + ": " + output);
}

inline void add_lyapunov_options(CLI::App& app, BeyondOptions& o) {
  add_mle_options(app, o, "column mle = X1(t) [1/s] (ensemble: its mean)");
  app.add_option("--deviation", o.deviation, "CSV t,site,share: the deviation vector along the chain (with --mle)");
  add_option(app, "--deviation-samples", o.deviation_samples, "uniform times of --deviation");
}

/// The library's choices (transport_choices.hpp), once --deviation is read.
inline BeyondChoices beyond_choices(const BeyondOptions& o) {
  if (!o.deviation.empty() && !o.mle) throw InvalidInput("--deviation: needs --mle");
  if (o.deviation_samples < 2)
    throw InvalidInput("--deviation-samples " + std::to_string(o.deviation_samples) + ": at least 2");
  BeyondChoices choices = o;
  if (o.deviation.empty()) choices.deviation_samples = 0;
  return choices;
}

/// The options bind straight into the library's choices (--beta, --fit, --active-window by the
/// text forms of transport_parameters); damping here, the tangent map as each tool adds it.
struct DynamicsOptions : TransportChoices, BeyondOptions {};

/// The kick's flags, and the run's: where the kick lands, the scheme, the samples, the fit, the
/// guards and damping (the library's table: transport_parameters, beyond_parameters).
inline void add_dynamics_options(CLI::App& app, DynamicsOptions& o) {
  add_parameters<TransportChoices>(app, o, transport_parameters(), {.except = {"fit_begin", "fit_end"}});
  add_parameters<BeyondChoices>(app, o, beyond_parameters(), {.except = {"mle", "renormalize", "deviation_samples"}});
}

/// Fills `c` from the options (granular::apply; integrator auto: settled with the step by
/// validate_and_settle). Needs c.n (for --site).
inline void apply(const DynamicsOptions& o, TransportCase& c) { granular::apply(o, beyond_choices(o), c); }

/// granular::validate_and_settle (case_settling.hpp): the cases validated with the errors in the
/// order a user can act on them (a --dt past the stability limit before a --fit-step judged on
/// it), the time step, and with `--integrator auto` the scheme first (SRKN14a at 5 µs where no
/// contact can open and it is cheaper, else SABA2C); then the --T warning, after the errors.
/// `cases`: one TransportCase or a std::vector of them.
template <class Cases>
nlohmann::json validate_and_settle(Cases& cases, const DynamicsOptions& o, bool dt_given) {
  std::string warning;
  nlohmann::json rule = granular::validate_and_settle(cases, o.integrator == "auto", dt_given, "--T", warning);
  warn({warning});
  return rule;
}

/// The flags of a mode kick, straight into the library's ModeKick.
inline void add_mode_kick_options(CLI::App& app, ModeKick& o) { add_parameters(app, o, mode_kick_parameters()); }

}  // namespace granular::tool
