#include "granular/study/transport_study.hpp"

#include <algorithm>
#include <cmath>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/ensemble/ensemble_runner.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"
#include "granular/model/chain.hpp"

namespace granular {

Kick parse_kick(const std::string& name) {
  if (name == "displacement") return Kick::displacement;
  if (name == "velocity") return Kick::velocity;
  throw InvalidInput("--ic '" + name + "': expected displacement or velocity");
}

std::string to_string(Kick kick) { return kick == Kick::displacement ? "displacement" : "velocity"; }

void validate(const TransportCase& c) {
  validate_probability(c.q);
  validate_size_ratio(c.xi);
  if (c.n < 2) throw InvalidInput("--N " + std::to_string(c.n) + ": a chain needs at least 2 beads");
  if (!std::isfinite(c.precompression) || c.precompression < 0)
    throw InvalidInput("--F0 " + format_number(c.precompression) + ": must be finite and >= 0");
  if (c.site >= c.n) throw InvalidInput("--site " + std::to_string(c.site + 1) + ": outside the chain of " + std::to_string(c.n) + " beads");
  if (c.realizations < 1) throw InvalidInput("--realizations: must be >= 1");
  if (c.fit && (!(c.fit_begin > 0) || !(c.fit_end > c.fit_begin))) throw InvalidInput("--fit: need 0 < start < stop");
  if (c.fit && c.fit_end > c.dynamics.duration * (1 + 1e-12))
    throw InvalidInput("--fit " + format_number(c.fit_begin) + ":" + format_number(c.fit_end) + ": reaches beyond --T " +
                       format_number(c.dynamics.duration));
  if (!(c.criterion.kappa > 0) || !std::isfinite(c.criterion.kappa))
    throw InvalidInput("--kappa " + format_number(c.criterion.kappa) + ": must be finite and > 0");
  const bool uses_alpha = c.kick == Kick::displacement || c.match_beta;
  if (uses_alpha && (!std::isfinite(c.alpha) || c.alpha == 0)) throw InvalidInput("--alpha " + format_number(c.alpha) + ": must be finite and non-zero [m]");
  if (c.kick == Kick::velocity && !c.match_beta && (!std::isfinite(c.beta) || c.beta == 0))
    throw InvalidInput("--beta " + format_number(c.beta) + ": must be finite and non-zero [m/s], or 'match'");
  if (c.n > 100000000) throw InvalidInput("--N " + std::to_string(c.n) + ": more than 1e8 beads");
  validate(c.dynamics, c.n);
}

nlohmann::json describe(const TransportCase& c) {
  const SpreadingConfig& d = c.dynamics;
  return {{"disorder", to_string(c.disorder)}, {"q", c.q}, {"xi", c.xi}, {"N", c.n}, {"F0_N", c.precompression},
          {"R1_m", c.r1}, {"ic", to_string(c.kick)}, {"alpha_m", c.alpha},
          {"beta_m_s", c.match_beta ? nlohmann::json("match") : nlohmann::json(c.beta)}, {"site", c.site + 1},
          {"T_s", d.duration}, {"dt_s", d.time_step}, {"integrator", d.integrator},
          {"force_law", to_string(d.force_law)}, {"samples", d.samples},
          {"sampling", d.sampling == Sampling::logarithmic ? "log" : "uniform"},
          {"active_window", d.window.enabled}, {"window_threshold", d.window.threshold},
          {"max_energy_error", d.max_energy_error}, {"stop_on_energy_error", d.stop_on_energy_error},
          {"seed", c.seed}, {"realizations", c.realizations},
          {"profile_realizations", std::min(c.profile_realizations, c.realizations)},
          {"material", {{"E_Pa", steel.young}, {"nu", steel.poisson}, {"rho_kg_m3", steel.density}}},
          {"walls", "flat, same material as the beads"}};
}

namespace {

// One realization as a row: m̃2 (S) | P⁻¹ (S) | energy error (S) | max error | wall energy | E_n(T) (N, only
// for the first profile_realizations: profiles are long, and checkpoints hold every row).
std::vector<double> realization_row(const TransportCase& c, std::uint64_t r) {
  const Configuration types = realization_configuration(c.disorder, c.q, c.n, c.seed, r);
  const Chain chain = make_chain(radii_of(types, c.r1, c.xi), c.precompression);
  State initial;
  if (c.kick == Kick::displacement) {
    initial = displacement_kick(chain, c.site, c.alpha);
  } else {
    const double beta =
        c.match_beta ? matched_velocity(make_force_law(c.dynamics.force_law, chain), chain, c.site, c.alpha) : c.beta;
    initial = velocity_kick(chain, c.site, beta);
  }
  SpreadingConfig config = c.dynamics;
  config.force_sites.clear();
  config.map_samples = 0;
  config.spectrum_samples = 0;
  const SpreadingResult result = run_spreading(chain, initial, config);
  std::vector<double> row;
  row.reserve(3 * result.t.size() + c.n + 2);
  row.insert(row.end(), result.m2.begin(), result.m2.end());
  row.insert(row.end(), result.ipr.begin(), result.ipr.end());
  row.insert(row.end(), result.energy_error.begin(), result.energy_error.end());
  row.push_back(result.max_energy_error);
  row.push_back(result.wall_energy);
  if (r < c.profile_realizations) row.insert(row.end(), result.final_energy.begin(), result.final_energy.end());
  return row;
}

std::vector<std::vector<double>> slice(const std::vector<std::vector<double>>& rows, std::size_t begin, std::size_t count) {
  std::vector<std::vector<double>> out;
  out.reserve(rows.size());
  for (const auto& row : rows) out.emplace_back(row.begin() + static_cast<long>(begin), row.begin() + static_cast<long>(begin + count));
  return out;
}

}  // namespace

TransportSummary run_transport_study(const TransportCase& c, const StudyRunOptions& options) {
  validate(c);
  const std::uint64_t total_steps = static_cast<std::uint64_t>(std::llround(c.dynamics.duration / c.dynamics.time_step));
  TransportSummary s;
  for (auto step : sample_steps(total_steps, c.dynamics.samples, c.dynamics.sampling))
    s.t.push_back(static_cast<double>(step) * c.dynamics.time_step);
  const std::size_t samples = s.t.size();

  EnsembleOptions ensemble;
  ensemble.realizations = c.realizations;
  ensemble.threads = options.threads;
  ensemble.checkpoint = options.checkpoint;
  ensemble.resume = options.resume;
  ensemble.parameters = describe(c).dump();
  ensemble.progress = options.progress;
  ensemble.cancelled = options.cancelled;
  const auto rows = run_ensemble(ensemble, [&](std::uint64_t r, int) {
    try {
      return realization_row(c, r);
    } catch (const NumericalError& e) {  // say which chain, so it can be replayed alone
      throw NumericalError("realization " + std::to_string(r) + " of seed " + std::to_string(c.seed) +
                           " (replay: spreading --seed " + std::to_string(c.seed) + " --realization " +
                           std::to_string(r) + "): " + e.what());
    }
  });
  if (!MpiContext::instance().root()) return s;

  const std::size_t width = 3 * samples + 2;
  const std::size_t profiled = std::min(c.profile_realizations, c.realizations);
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (rows[r].size() != width + (r < profiled ? c.n : 0))
      throw NumericalError("realization " + std::to_string(r) + " has a row of the wrong length");
  s.realizations = rows.size();
  s.m2 = summarize(slice(rows, 0, samples));
  s.ipr = summarize(slice(rows, samples, samples));
  s.energy_error = summarize(slice(rows, 2 * samples, samples));
  for (const auto& row : rows) {
    s.max_energy_error = std::fmax(s.max_energy_error, row[3 * samples]);
    s.reached_walls += row[3 * samples + 1] > c.dynamics.wall_warning;
  }
  if (profiled > 0) {
    const std::vector<std::vector<double>> with_profile(rows.begin(), rows.begin() + static_cast<long>(profiled));
    s.profile = summarize(slice(with_profile, width, c.n));
  }
  if (!c.fit) return s;
  s.gamma = analyze_power_law(s.t, s.m2.mean, c.fit_begin, c.fit_end, c.criterion);
  std::vector<double> participation;  // P⁻¹ ∝ t^−η  ⇔  1/P⁻¹ ∝ t^η
  for (double p : s.ipr.mean) participation.push_back(1 / p);
  s.eta = analyze_power_law(s.t, participation, c.fit_begin, c.fit_end, c.criterion);
  return s;
}

}  // namespace granular
