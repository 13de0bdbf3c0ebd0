#pragma once
// The options of a kicked-chain run, shared by `spreading` and `exponents` so that the same case
// gives the same numbers from both: one default for every physical choice (the paper's: α = 1e-7 m,
// β = 8e-3 m/s, the kick at the centre bead, m̃2 about the excited site, fits on 4–10 ms sampled
// every 10 µs, t* = 4 ms, κ = 0.1). The library's messages name
// parameters (`fit_step`, `t_star`); tool::run tells them as these flags (`--fit-step`, `--t-star`).
// Beyond the paper (docs/physics.md, "Nonlinear dynamics"): dissipation (--damping-time, --kk-gamma)
// and the maximal Lyapunov exponent by the tangent map (`spreading --mle`, `exponents --mle`).
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "granular/case/case_settling.hpp"
#include "granular/case/transport_parameters.hpp"
#include "granular/study/transport_study.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// --mle (its help ending in `output`: what the tool writes of it) and --renormalize.
inline void add_mle_options(CLI::App& app, TransportCase& o, const std::string& output) {
  auto options = add_parameters(app, o, transport_parameters(), {.only = {"mle", "renormalize"}});
  options["mle"]->description(options["mle"]->get_description() + ": " + output);
}

/// The kick's flags, and the run's, bound to the case: where the kick lands, the scheme, the
/// samples, the fit (--beta, --fit, --active-window and the enums by the text forms of
/// transport_parameters), the guards and damping; the tangent map as each tool adds it.
inline void add_dynamics_options(CLI::App& app, TransportCase& run) {
  add_parameters(app, run, transport_parameters(),
                 {.except = {"fit_begin", "fit_end", "mle", "renormalize", "deviation_samples", "lyapunov_vectors",
                             "covariant_vectors", "covariant_transient"}});
}

/// granular::validate_and_settle (case_settling.hpp): the cases validated with the errors in the
/// order a user can act on them (a --dt past the stability limit before a --fit-step judged on
/// it), the time step, and with `--integrator auto` the scheme first (SRKN14a at 5 µs where no
/// contact can open and it is cheaper, else SABA2C); then the --T warning, after the errors.
/// `cases`: one TransportCase or a std::vector of them.
template <class Cases>
nlohmann::json validate_and_settle(Cases& cases) {
  std::string warning;
  nlohmann::json rule = granular::validate_and_settle(cases, "--T", warning);
  warn({warning});
  return rule;
}

}  // namespace granular::tool
