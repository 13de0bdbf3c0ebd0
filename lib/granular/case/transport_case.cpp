#include "granular/case/transport_case.hpp"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "granular/case/spreading_outputs.hpp"
#include "granular/case/transport_parameters.hpp"
#include "granular/detail/enum_names.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/error.hpp"
#include "granular/model/chain.hpp"
#include "granular/number_format.hpp"
#include "granular/parameter_json.hpp"

namespace granular {

constexpr auto kick_names =
    detail::enum_names<Kick>("ic",
                             {{Kick::displacement, "displacement"}, {Kick::velocity, "velocity"}, {Kick::mode, "mode"}});

Kick parse_kick(const std::string& name) { return kick_names.parse(name); }

std::string to_string(Kick kick) { return std::string(kick_names.name_of(kick)); }

namespace {
/// The mode kick of a case: its amplitude is α unless an energy is given.
ModeKick mode_of(const TransportCase& c) {
  ModeKick m = c.mode;
  if (m.energy == 0) m.amplitude = c.alpha;
  return m;
}
}  // namespace

void refuse_spectrum_in_ensemble(const SpreadingRunConfig& d) {
  if (d.lyapunov_vectors > 0)
    throw InvalidInput("lyapunov_vectors", " " + std::to_string(d.lyapunov_vectors) +
                                               ": one realization only (an ensemble does not average the spectrum)");
  if (d.covariant_vectors > 0)
    throw InvalidInput("covariant_vectors", " " + std::to_string(d.covariant_vectors) +
                                                ": one realization only (an ensemble does not average the vectors)");
}

std::size_t kicked_bead(const TransportCase& c) { return c.site == 0 ? (c.chain.size() - 1) / 2 : c.site - 1; }

namespace {
/// The checks of the choices a front end sets straight in the case (transport_parameters()).
void validate_choices(const TransportCase& c) {
  refuse_unmet_needs(c, transport_parameters());  // `energy_guard` with no guard is refused, not ignored
  check_ranges(c, transport_parameters());        // the rows' own ranges (`kappa` > 0, …)
  validate_outputs(c);
  const std::size_t n = c.chain.size();
  if (c.site > n)
    throw InvalidInput("site", " " + std::to_string(c.site) + ": outside the chain of " + std::to_string(n) +
                                   " beads (1..N, 0 = centre)");
  const SpreadingRunConfig& d = c.dynamics;
  if (d.spread.samples < 2) throw InvalidInput("samples", " " + std::to_string(d.spread.samples) + ": at least 2");
  if (!(c.fit_begin > 0) || !(c.fit_end > c.fit_begin) || !std::isfinite(c.fit_end))
    throw InvalidInput("fit", " " + format_number(c.fit_begin) + ":" + format_number(c.fit_end) +
                                  ": expected start:stop with 0 < start < stop [s]");
  if (c.bootstrap.resamples < 2)
    throw InvalidInput("bootstrap", " " + std::to_string(c.bootstrap.resamples) + ": at least 2 resamples");
  validate(d.integration.damping);
  if (d.integration.lyapunov.renormalize_every < 1)
    throw InvalidInput("renormalize", " " + std::to_string(d.integration.lyapunov.renormalize_every) + ": at least 1");
  if (d.deviation_samples == 1) throw InvalidInput("deviation_samples", " 1: 0 (none) or at least 2");
  if (c.realizations > 1) refuse_spectrum_in_ensemble(d);
}
}  // namespace

void validate_before_time_step(const TransportCase& c) {
  validate(c.chain);
  validate_choices(c);
  const std::size_t n = c.chain.size();
  const std::size_t site = kicked_bead(c);
  if (const auto* d = c.chain.as<TwoTypeDraw>(); d && d->centred && site != (n - 1) / 2)
    throw InvalidInput("site", " " + std::to_string(site + 1) + ": a chain drawn from its centre is kicked there (" +
                                   std::to_string((n + 1) / 2) + ")");
  if (c.realizations < 1) throw InvalidInput("realizations", ": must be >= 1");
  IntegrationConfig integration = integration_config(c.dynamics);
  if (c.time_step) integration.time_step = *c.time_step;  // the τ given, judged before the rule settles it
  validate_step_and_duration(integration);                // T and τ first: a fit window is judged against them
  if (c.fit && c.fit_end > c.dynamics.integration.duration * (1 + 1e-12))
    throw InvalidInput("fit", " " + format_number(c.fit_begin) + ":" + format_number(c.fit_end) +
                                  ": reaches beyond the duration T = " + format_number(c.dynamics.integration.duration));
  if (!(c.criterion.t_start >= 0) || !std::isfinite(c.criterion.t_start))
    throw InvalidInput("t_star", " " + format_number(c.criterion.t_start) + " s: must be finite and >= 0");
  if (c.kick == Kick::mode) validate(mode_of(c), n);
  if (c.kick == Kick::mode && !(c.chain.F0 > 0))  // found before any run, not in realization 0
    throw InvalidInput("precompression", " " + format_number(c.chain.F0) +
                                             ": a mode kick needs F0 > 0 (the sonic vacuum has no "
                                             "linear modes)");
  const bool uses_alpha = c.kick == Kick::displacement || !c.beta || (c.kick == Kick::mode && c.mode.energy == 0);
  if (uses_alpha && (!std::isfinite(c.alpha) || c.alpha == 0))
    throw InvalidInput("alpha", " " + format_number(c.alpha) + ": must be finite and non-zero [m]");
  if (c.kick == Kick::velocity && c.beta && (!std::isfinite(*c.beta) || *c.beta == 0))
    throw InvalidInput("beta", " " + format_number(*c.beta) + ": must be finite and non-zero [m/s], or 'match'");
  if (c.fit && !(std::isfinite(c.fit_step) && c.fit_step > 0))
    throw InvalidInput("fit_step", " " + format_number(c.fit_step) + " s: must be finite and > 0");
}

void validate(const TransportCase& c) {
  validate_before_time_step(c);
  const std::size_t n = c.chain.size();
  validate(c.dynamics, n);  // on τ's grid: T and every sampling a whole number of steps
  const SpreadingRunConfig config = spreading_config(c);
  validate(config, n);
  if (c.fit) {  // a fit that cannot work is bad input, found before the run rather than after it
    std::vector<double> t;
    for (auto step : sample_steps(config)) t.push_back(static_cast<double>(step) * config.integration.time_step);
    try {
      windowed_exponent(t, t, c.fit_begin, c.fit_end);
    } catch (const InvalidInput& e) {
      throw InvalidInput("fit", " " + format_number(c.fit_begin) + ":" + format_number(c.fit_end) +
                                    ": too few samples in a sub-window (" + e.what() + ")");
    }
  }
}

SpreadingRunConfig spreading_config(const TransportCase& c) {
  SpreadingRunConfig config = c.dynamics;
  config.spread.site = kicked_bead(c);
  config.spread.dense = c.fit ? DenseGrid{c.fit_begin, c.fit_end, c.fit_step} : DenseGrid{};
  return config;
}

KickedChain kick(const TransportCase& c, const Chain& chain) {
  const std::size_t site = kicked_bead(c);
  if (c.kick == Kick::displacement) return {displacement_kick(chain, site, c.alpha), 0.0, {}};
  if (c.kick == Kick::mode) {
    ModeKickResult mode = mode_kick(chain, c.dynamics.integration.force_law, mode_of(c));
    State initial = mode.initial;
    return {std::move(initial), 0.0, std::move(mode)};
  }
  const double beta =
      c.beta ? *c.beta : matched_velocity(make_force_law(c.dynamics.integration.force_law, chain), chain, site, c.alpha);
  return {velocity_kick(chain, site, beta), beta, {}};
}

nlohmann::json describe(const TransportCase& c) {
  nlohmann::json j = describe_rows(c, case_parameters());
  describe_fields(c.chain, j);
  // Set by the study rather than a front end (profiles are long; checkpoints hold every row).
  j["profile_realizations"] = std::min(c.profile_realizations, c.realizations);
  return j;
}

TransportCase parse_case(const nlohmann::json& j) {
  const ParameterTable<TransportCase>& rows = case_parameters();
  for (const Parameter<TransportCase>& p : rows)
    if (p.described && !j.contains(p.name))
      throw InvalidInput(p.name, j.contains("dt_s") ? ": not in the case, which is granular 0.2.0's (its keys were "
                                                      "renamed since: CHANGELOG.md); replay it with 0.2.0"
                                                    : ": not in the case");
  TransportCase c;
  c.chain = parse_recipe_fields(j);
  c = parse_rows(j, rows, std::move(c));
  try {
    c.profile_realizations = j.at("profile_realizations").get<std::size_t>();
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInput("profile_realizations", std::string(": ") + e.what());
  }
  if (c.time_step) c.dynamics.integration.time_step = *c.time_step;  // a settled case: its τ is given
  fit_within_duration(c);
  return c;
}

}  // namespace granular
