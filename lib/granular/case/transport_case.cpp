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
double finite_non_negative(double value, const char* name) {
  if (!(value >= 0) || !std::isfinite(value))
    throw InvalidInput(name, " " + format_number(value) + ": must be finite and >= 0");
  return value;
}
/// The checks of the choices a front end sets straight in the case (transport_parameters()).
void validate_choices(const TransportCase& c) {
  refuse_unmet_needs(c, transport_parameters());  // `energy_guard` with no guard is refused, not ignored
  validate_outputs(c);
  const std::size_t n = c.chain.size();
  if (c.site > n)
    throw InvalidInput("site", " " + std::to_string(c.site) + ": outside the chain of " + std::to_string(n) +
                                   " beads (1..N, 0 = centre)");
  const SpreadingRunConfig& d = c.dynamics;
  if (d.spread.samples < 2) throw InvalidInput("samples", " " + std::to_string(d.spread.samples) + ": at least 2");
  finite_non_negative(d.integration.window.threshold, "window_threshold");
  finite_non_negative(d.integration.integrator.tolerance.max_step, "reference_max_step");
  finite_non_negative(d.spread.max_energy_error, "max_energy_error");
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
  if (!(c.criterion.kappa > 0) || !std::isfinite(c.criterion.kappa))
    throw InvalidInput("kappa", " " + format_number(c.criterion.kappa) + ": must be finite and > 0");
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

static nlohmann::json describe_conservative(const TransportCase& c) {
  const SpreadingRunConfig& d = c.dynamics;
  const bool uses_alpha = c.kick == Kick::displacement || !c.beta || (c.kick == Kick::mode && c.mode.energy == 0);
  nlohmann::json beta = nullptr;  // the values used: α only where the kick uses it, β only for a velocity kick
  if (c.kick == Kick::velocity) beta = c.beta ? nlohmann::json(*c.beta) : nlohmann::json("match");
  nlohmann::json described = {{"ic", to_string(c.kick)},
                              {"alpha_m", uses_alpha ? nlohmann::json(c.alpha) : nullptr},
                              {"beta_m_s", beta},
                              {"site", kicked_bead(c) + 1},
                              {"m2_centre", to_string(c.centre)},
                              {"T_s", d.integration.duration},
                              {"dt_s", c.time_step.value_or(d.integration.time_step)},  // settled: the same
                              {"integrator", d.integration.integrator.name()},
                              {"force_law", to_string(d.integration.force_law)},
                              {"samples", d.spread.samples},
                              {"sampling", to_string(d.spread.sampling)},
                              {"fit_s", c.fit ? nlohmann::json({c.fit_begin, c.fit_end}) : nlohmann::json(nullptr)},
                              {"fit_step_s", c.fit_step},
                              {"kappa", c.criterion.kappa},
                              {"t_star_s", c.criterion.t_start},
                              {"bootstrap_resamples", c.bootstrap.resamples},
                              {"bootstrap_seed", c.bootstrap.seed},
                              {"active_window", d.integration.window.enabled},
                              {"window_threshold", d.integration.window.threshold},
                              {"max_energy_error", d.spread.max_energy_error},
                              {"stop_on_energy_error", d.spread.stop_on_energy_error},
                              {"realizations", c.realizations},
                              {"profile_realizations", std::min(c.profile_realizations, c.realizations)}};
  describe_fields(c.chain, described);
  if (c.kick == Kick::mode)  // only then: every other case keeps its identity (and its checkpoints)
    described["mode_kick"] = {{"mode", c.mode.mode == 0 ? nlohmann::json(nullptr) : nlohmann::json(c.mode.mode)},
                              {"near_khz", c.mode.near_khz ? nlohmann::json(*c.mode.near_khz) : nlohmann::json(nullptr)},
                              {"energy_J", c.mode.energy == 0 ? nlohmann::json(nullptr) : nlohmann::json(c.mode.energy)}};
  return described;
}

nlohmann::json describe(const TransportCase& c) {
  nlohmann::json j = describe_conservative(c);
  // Only when switched on, so that conservative runs keep their parameters (and checkpoints).
  const SpreadingRunConfig& d = c.dynamics;
  if (d.integration.damping.any())
    j["damping"] = {{"time_s", d.integration.damping.time}, {"kk_gamma_s", d.integration.damping.kk_gamma}};
  if (d.integration.integrator.reference)
    j["reference_max_step_s"] = d.integration.integrator.tolerance.max_step;  // only then it matters
  if (d.integration.lyapunov.enabled)
    j["lyapunov"] = {{"renormalize_every", d.integration.lyapunov.renormalize_every},
                     {"norm_time_unit_s", d.integration.lyapunov.time_unit},
                     {"initial_deviation", "du = 1, dv = 1/time_unit on the kicked bead"}};
  if (d.lyapunov_vectors > 0)
    j["lyapunov_spectrum"] = {{"vectors", d.lyapunov_vectors},
                              {"orthonormalize_every", d.integration.lyapunov.renormalize_every},
                              {"seed", LyapunovSpectrumConfig{}.seed}};
  if (d.covariant_vectors > 0 || d.covariant_transient) {  // a transient alone is refused, but not unsaid
    const CovariantVectorsConfig clv = covariant_config(d);
    j["covariant_vectors"] = {{"vectors", d.covariant_vectors},
                              {"transient_s", d.covariant_transient ? nlohmann::json(*d.covariant_transient)
                                                                    : nlohmann::json(nullptr)},
                              {"transient_steps", clv.forward_transient},
                              {"orthonormalize_every", clv.orthonormalize_every},
                              {"seed", clv.seed}};
  }
  return j;
}

TransportCase parse_case(const nlohmann::json& j) {
  TransportCase c;
  try {
    c.chain = parse_recipe_fields(j);
    c.kick = parse_kick(j.at("ic").get<std::string>());
    if (!j.at("alpha_m").is_null()) c.alpha = j.at("alpha_m").get<double>();
    const auto& beta = j.at("beta_m_s");
    if (beta.is_string() && beta.get<std::string>() != "match") throw InvalidInput("beta_m_s", ": a number or 'match'");
    if (beta.is_string()) c.beta.reset();
    if (beta.is_number()) c.beta = beta.get<double>();
    c.site = j.at("site").get<std::size_t>();
    c.centre = parse_spread_centre(j.at("m2_centre").get<std::string>());
    SpreadingRunConfig& d = c.dynamics;
    d.integration.duration = j.at("T_s").get<double>();
    d.integration.time_step = j.at("dt_s").get<double>();
    c.time_step = d.integration.time_step;  // a described case was settled: its τ is given
    d.integration.integrator = parse_integrator(j.at("integrator").get<std::string>());
    if (j.contains("reference_max_step_s"))
      d.integration.integrator.tolerance.max_step = j.at("reference_max_step_s").get<double>();
    d.integration.force_law = parse_force_law(j.at("force_law").get<std::string>());
    d.spread.samples = j.at("samples").get<std::size_t>();
    d.spread.sampling = parse_sampling(j.at("sampling").get<std::string>());
    c.fit = !j.at("fit_s").is_null();
    if (c.fit) c.fit_begin = j.at("fit_s").at(0).get<double>(), c.fit_end = j.at("fit_s").at(1).get<double>();
    c.fit_step = j.at("fit_step_s").get<double>();
    c.criterion.kappa = j.at("kappa").get<double>();
    c.criterion.t_start = j.at("t_star_s").get<double>();
    c.bootstrap.resamples = j.at("bootstrap_resamples").get<std::size_t>();
    c.bootstrap.seed = j.at("bootstrap_seed").get<std::uint64_t>();
    d.integration.window.enabled = j.at("active_window").get<bool>();
    d.integration.window.threshold = j.at("window_threshold").get<double>();
    d.spread.max_energy_error = j.at("max_energy_error").get<double>();
    d.spread.stop_on_energy_error = j.at("stop_on_energy_error").get<bool>();
    c.realizations = j.at("realizations").get<std::size_t>();
    c.profile_realizations = j.at("profile_realizations").get<std::size_t>();
    if (j.contains("mode_kick")) {
      const auto& m = j.at("mode_kick");
      if (!m.at("mode").is_null()) c.mode.mode = m.at("mode").get<long>();
      if (!m.at("near_khz").is_null()) c.mode.near_khz = m.at("near_khz").get<double>();
      if (!m.at("energy_J").is_null()) c.mode.energy = m.at("energy_J").get<double>();
    }
    if (j.contains("damping")) {
      d.integration.damping.time = j.at("damping").at("time_s").get<double>();
      d.integration.damping.kk_gamma = j.at("damping").at("kk_gamma_s").get<double>();
    }
    if (j.contains("lyapunov")) {
      d.integration.lyapunov.enabled = true;
      d.integration.lyapunov.renormalize_every = j.at("lyapunov").at("renormalize_every").get<std::size_t>();
      d.integration.lyapunov.time_unit = j.at("lyapunov").at("norm_time_unit_s").get<double>();
    }
    if (j.contains("lyapunov_spectrum"))
      d.lyapunov_vectors = j.at("lyapunov_spectrum").at("vectors").get<std::size_t>();
    if (j.contains("covariant_vectors")) {
      d.covariant_vectors = j.at("covariant_vectors").at("vectors").get<std::size_t>();
      if (const auto& t = j.at("covariant_vectors").at("transient_s"); !t.is_null())
        d.covariant_transient = t.get<double>();
    }
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInput("case", std::string(": ") + e.what());
  }
  return c;
}

}  // namespace granular
