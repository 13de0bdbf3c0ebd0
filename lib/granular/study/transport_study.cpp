#include "granular/study/transport_study.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "granular/dynamics/spread.hpp"
#include "granular/ensemble/ensemble_runner.hpp"
#include "granular/error.hpp"
#include "granular/lanes/lane_propagator.hpp"
#include "granular/lanes/spread_in_lanes.hpp"
#include "granular/model/chain.hpp"
#include "granular/number_format.hpp"
#include "granular/parallel/mpi_context.hpp"

namespace granular {

TransportExponents transport_exponents(const TransportCase& c, const std::vector<double>& t,
                                       const std::vector<double>& m2_site, const std::vector<double>& m2_centroid,
                                       const std::vector<double>& ipr) {
  TransportExponents e;
  e.gamma_site = report_exponent(t, m2_site, c.fit_begin, c.fit_end, c.criterion);
  e.gamma_centroid = report_exponent(t, m2_centroid, c.fit_begin, c.fit_end, c.criterion);
  std::vector<double> participation;  // P⁻¹ ∝ t^−η  ⇔  1/P⁻¹ ∝ t^η
  for (double p : ipr) participation.push_back(1 / p);
  e.eta = report_exponent(t, participation, c.fit_begin, c.fit_end, c.criterion);
  return e;
}

nlohmann::json to_json(const ExponentReport& r) {
  const auto estimate = [](const ExponentEstimate& e, double realization_error) {
    return nlohmann::json{{"value", e.value},
                          {"window_spread", e.error},
                          {"sub_windows", e.slopes},
                          {"realization_error", std::isnan(realization_error) ? nlohmann::json(nullptr)
                                                                              : nlohmann::json(realization_error)}};
  };
  return {{"shown", r.starred() ? "mean_log_derivative" : "fit"},
          {"starred", r.starred()},
          {"value", r.shown().value},
          {"window_spread", r.shown().error},
          {"fit", estimate(r.fit, r.fit_realization_error)},
          {"mean_log_derivative", estimate(r.mean_ld, r.mean_ld_realization_error)},
          {"power_law", r.verdict.power_law},
          {"worst_log_derivative_deviation", r.verdict.worst_deviation},
          {"worst_deviation_time_s", r.verdict.worst_time}};
}

nlohmann::json to_json(const TransportExponents& e, SpreadCentre shown) {
  const ExponentReport& g = e.gamma(shown);
  const auto real = [](double x) { return std::isnan(x) ? nlohmann::json(nullptr) : nlohmann::json(x); };
  return {
      {"gamma", g.shown().value},
      {"gamma_err", g.shown().error},
      {"gamma_real_err", real(g.shown_realization_error())},
      {"eta", e.eta.shown().value},
      {"eta_err", e.eta.shown().error},
      {"eta_real_err", real(e.eta.shown_realization_error())},
      {"power_law", g.verdict.power_law},
      {"m2_centre", to_string(shown)},
      {"exponents",
       {{"gamma_site", to_json(e.gamma_site)}, {"gamma_centroid", to_json(e.gamma_centroid)}, {"eta", to_json(e.eta)}}}};
}

std::vector<std::string> warnings(const SpreadingResult& r, const SpreadingRunConfig& config) {
  std::vector<std::string> w;
  if (r.reached_walls)
    w.push_back("energy reached the walls ((E_1 + E_N)/H0 up to " + format_number(r.wall_energy) +
                "): the chain is too short for T");
  if (r.energy_guard_time >= 0)
    w.push_back("relative energy error passed the guard max_energy_error = " +
                format_number(config.spread.max_energy_error) + " at t = " + format_number(r.energy_guard_time) + " s");
  return w;
}

std::vector<std::string> warnings(const TransportSummary& s, const SpreadingRunConfig& config) {
  std::vector<std::string> w;
  if (config.spread.max_energy_error > 0 && s.max_energy_error > config.spread.max_energy_error)
    w.push_back("relative energy error reached " + format_number(s.max_energy_error) +
                ", past the guard max_energy_error = " + format_number(config.spread.max_energy_error));
  if (s.reached_walls > 0)
    w.push_back("energy reached the walls in " + std::to_string(s.reached_walls) + " of " +
                std::to_string(s.realizations) + " realizations: the chain is too short for T");
  return w;
}

std::string excluded_note(const TransportCase& c, const TransportSummary& s) {
  if (s.excluded.empty()) return "";
  return std::to_string(s.excluded.size()) + " failed realization(s) of " + std::to_string(c.realizations) + " left out";
}

namespace {

// What one realization leaves behind, by name. Its row in the ensemble's results and checkpoints
// keeps one order, which every checkpoint already written resumes with: m̃2 about the site | m̃2
// about the centroid | P⁻¹ | energy error (each on the S sample times) | max energy error | wall
// energy | X1 on the S sample times (only with the tangent map) | E_n(T) (N, only for the first
// profile_realizations: profiles are long, and checkpoints hold every row).
struct RealizationRecord {
  std::vector<double> m2_site, m2_centroid, ipr, energy_error;  ///< on the S sample times
  double max_energy_error = 0, wall_energy = 0;
  std::vector<double> mle;      ///< X1(t) on the sample times; empty without the tangent map
  std::vector<double> profile;  ///< E_n(T); empty unless profiled

  std::vector<double> row() const {
    std::vector<double> out;
    out.reserve(4 * m2_site.size() + 2 + mle.size() + profile.size());
    for (const auto* s : {&m2_site, &m2_centroid, &ipr, &energy_error}) out.insert(out.end(), s->begin(), s->end());
    out.push_back(max_energy_error);
    out.push_back(wall_energy);
    out.insert(out.end(), mle.begin(), mle.end());
    out.insert(out.end(), profile.begin(), profile.end());
    return out;
  }

  /// The record a row of S = `samples` holds, with X1 when `with_mle` and a profile of `beads`
  /// (0: none); nullopt when the row has another length.
  static std::optional<RealizationRecord> of_row(const std::vector<double>& row, std::size_t samples, bool with_mle,
                                                 std::size_t beads) {
    if (row.size() != 4 * samples + 2 + (with_mle ? samples : 0) + beads) return std::nullopt;
    auto next = row.begin();
    const auto take = [&](std::size_t n) {
      std::vector<double> part(next, next + static_cast<long>(n));
      next += static_cast<long>(n);
      return part;
    };
    RealizationRecord r;
    r.m2_site = take(samples);
    r.m2_centroid = take(samples);
    r.ipr = take(samples);
    r.energy_error = take(samples);
    r.max_energy_error = *next++;
    r.wall_energy = *next++;
    if (with_mle) r.mle = take(samples);
    r.profile = take(beads);
    return r;
  }
};

/// One realization of `c`, measured by what the ensemble keeps: the energy spread, X1(t) with the
/// tangent map, and E_n(T) when profiled.
/// What the ensemble keeps of one realization, measured by these observers.
struct RealizationObservers {
  EnergySpreadObserver energy;
  FinalStateObserver final_state;
  std::optional<LyapunovObserver> lyapunov;

  explicit RealizationObservers(const SpreadingRunConfig& run) : energy(run.spread) {
    if (run.integration.lyapunov.enabled) lyapunov.emplace(lyapunov_settings(run));
  }
  std::vector<Observer*> list() {
    std::vector<Observer*> out{&energy, &final_state};
    if (lyapunov) out.push_back(&*lyapunov);
    return out;
  }
  RealizationRecord record(const TransportCase& c, std::uint64_t r);
};

RealizationRecord measure_realization(const TransportCase& c, std::uint64_t r) {
  const Chain chain = c.chain.chain(r);
  const SpreadingRunConfig run = spreading_config(c);
  RealizationObservers observers(run);
  spread(chain, kick(c, chain).initial, integration_config(run), observers.list());
  return observers.record(c, r);
}

RealizationRecord RealizationObservers::record(const TransportCase& c, std::uint64_t r) {
  RealizationRecord record{.m2_site = std::move(energy.m2),
                           .m2_centroid = std::move(energy.m2_centroid),
                           .ipr = std::move(energy.ipr),
                           .energy_error = std::move(energy.energy_error),
                           .max_energy_error = energy.max_energy_error,
                           .wall_energy = energy.wall_energy,
                           .mle = {},
                           .profile = {}};
  if (lyapunov) record.mle = std::move(lyapunov->mle);
  if (r < c.profile_realizations) record.profile = std::move(final_state.energy);
  return record;
}

/// Realizations `rs` of `c` (as many as LanePropagator::width() at most), side by side in vector
/// lanes: each record (or failure) the same bits as measure_realization's.
std::vector<std::pair<RealizationRecord, std::exception_ptr>> measure_realizations_in_lanes(
    const TransportCase& c, std::span<const std::uint64_t> rs) {
  const SpreadingRunConfig run = spreading_config(c);
  std::vector<Chain> chains;
  std::vector<State> initials;
  std::vector<RealizationObservers> observers;
  std::vector<std::vector<Observer*>> lists;
  chains.reserve(rs.size());
  observers.reserve(rs.size());  // list() points into them
  for (const std::uint64_t r : rs) {
    chains.push_back(c.chain.chain(r));
    initials.push_back(kick(c, chains.back()).initial);
    lists.push_back(observers.emplace_back(run).list());
  }
  const std::vector<LaneRun> runs = spread_in_lanes(chains, initials, integration_config(run), lists);
  std::vector<std::pair<RealizationRecord, std::exception_ptr>> out;
  for (std::size_t l = 0; l < rs.size(); ++l)
    out.emplace_back(runs[l].failure ? RealizationRecord{} : observers[l].record(c, rs[l]), runs[l].failure);
  return out;
}

/// The non-empty `field` of every record, in order (views: the records hold the series).
std::vector<std::span<const double>> series_of(const std::vector<RealizationRecord>& records,
                                               std::vector<double> RealizationRecord::*field) {
  std::vector<std::span<const double>> out;
  out.reserve(records.size());
  for (const auto& record : records)
    if (!(record.*field).empty()) out.emplace_back(record.*field);
  return out;
}

// Realization errors of γ (both centres) and η: the bootstrap over the records, on the fit
// window's samples only (the only ones the statistics read).
void add_realization_errors(const TransportCase& c, const std::vector<double>& t,
                            const std::vector<RealizationRecord>& records, int threads, TransportExponents& e) {
  std::vector<std::size_t> window;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= c.fit_begin * (1 - 1e-9) && t[i] <= c.fit_end * (1 + 1e-9)) window.push_back(i);
  const std::size_t g = window.size();
  std::vector<double> t_fit;
  for (std::size_t i : window) t_fit.push_back(t[i]);
  std::vector<double> matrix;  // R × 3g: m̃2 site | m̃2 centroid | 1/P⁻¹ on the window
  matrix.reserve(records.size() * 3 * g);
  for (const auto& record : records) {
    for (std::size_t i : window) matrix.push_back(record.m2_site[i]);
    for (std::size_t i : window) matrix.push_back(record.m2_centroid[i]);
    for (std::size_t i : window) matrix.push_back(record.ipr[i]);
  }
  std::vector<double> sd(6, 0.0);
  if (records.size() > 1) {
    BootstrapConfig config = c.bootstrap;
    config.threads = threads;
    sd = bootstrap_standard_deviation(
        matrix, 3 * g,
        [&](const std::vector<double>& mean) {
          std::vector<double> out;
          for (std::size_t k = 0; k < 3; ++k) {
            std::vector<double> y(mean.begin() + static_cast<long>(k * g),
                                  mean.begin() + static_cast<long>((k + 1) * g));
            if (k == 2)
              for (double& p : y) p = 1 / p;
            out.push_back(windowed_exponent(t_fit, y, c.fit_begin, c.fit_end).value);
            out.push_back(mean_log_derivative(t_fit, y, c.fit_begin, c.fit_end));
          }
          return out;
        },
        config);
  }
  ExponentReport* reports[] = {&e.gamma_site, &e.gamma_centroid, &e.eta};
  for (std::size_t k = 0; k < 3; ++k) {
    reports[k]->fit_realization_error = sd[2 * k];
    reports[k]->mean_ld_realization_error = sd[2 * k + 1];
  }
}

}  // namespace

TransportSummary run_transport_study(const TransportCase& c, const StudyRunOptions& options) {
  validate(c);
  refuse_spectrum_in_ensemble(c.dynamics);  // even of one realization: an ensemble's records hold no spectrum
  const SpreadingRunConfig config = spreading_config(c);
  TransportSummary s;
  for (auto step : sample_steps(config)) s.t.push_back(static_cast<double>(step) * config.integration.time_step);
  const std::size_t samples = s.t.size();

  EnsembleOptions ensemble;
  ensemble.realizations = c.realizations;
  ensemble.threads = options.threads;
  ensemble.checkpoint = options.checkpoint;
  ensemble.resume = options.resuming();
  ensemble.fresh = options.fresh;
  ensemble.accept_other_version = options.accept_other_version;
  ensemble.parameters = describe(c).dump();
  ensemble.progress = options.progress;
  ensemble.cancelled = options.cancelled;
  // A failed realization says which chain, so it can be replayed alone; or is logged as failed
  // (an empty row): left out, listed.
  const auto failed = [&](std::uint64_t r, const std::exception_ptr& failure) -> BatchedRow {
    try {
      std::rethrow_exception(failure);
    } catch (const NumericalError& e) {
      if (options.skip_failed) return {};
      return {{}, std::make_exception_ptr(RealizationFailed(c, r, e.what()))};
    }
  };
  const bool lanes = !options.one_at_a_time && runs_in_lanes(integration_config(config));
  std::vector<std::vector<double>> rows =
      run_ensemble_in_batches(ensemble, lanes ? LanePropagator::width() : 1, [&](std::span<const std::uint64_t> rs, int) {
        std::vector<BatchedRow> out;
        if (rs.size() > 1) {
          for (auto& [record, failure] : measure_realizations_in_lanes(c, rs))
            out.push_back(failure ? failed(rs[out.size()], failure) : BatchedRow{record.row(), nullptr});
          return out;
        }
        try {
          out.push_back({measure_realization(c, rs[0]).row(), nullptr});
        } catch (const NumericalError&) {
          out.push_back(failed(rs[0], std::current_exception()));
        }
        return out;
      });
  if (!MpiContext::instance().root()) return s;

  const bool with_mle = c.dynamics.integration.lyapunov.enabled;
  const std::size_t all_profiled = std::min(c.profile_realizations, c.realizations);
  std::vector<RealizationRecord> records;
  records.reserve(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (rows[r].empty()) {  // failed, here or in the run this one resumes
      if (!options.skip_failed)
        throw RealizationFailed(c, r, "it failed in the interrupted run (which was told to skip failures)");
      s.excluded.push_back(r);
      continue;
    }
    auto record = RealizationRecord::of_row(rows[r], samples, with_mle, r < all_profiled ? c.chain.size() : 0);
    if (!record) throw NumericalError("realization " + std::to_string(r) + " has a row of the wrong length");
    records.push_back(std::move(*record));
    std::vector<double>().swap(rows[r]);
  }
  if (records.empty())
    throw NumericalError("every one of the " + std::to_string(c.realizations) + " realizations failed");
  s.realizations = records.size();
  s.m2 = summarize(series_of(records, &RealizationRecord::m2_site));
  s.m2_centroid = summarize(series_of(records, &RealizationRecord::m2_centroid));
  s.ipr = summarize(series_of(records, &RealizationRecord::ipr));
  s.energy_error = summarize(series_of(records, &RealizationRecord::energy_error));
  for (const auto& record : records) {
    s.max_energy_error = std::fmax(s.max_energy_error, record.max_energy_error);
    s.reached_walls += record.wall_energy > c.dynamics.spread.wall_warning;
  }
  if (with_mle) s.mle = summarize(series_of(records, &RealizationRecord::mle));
  s.profile = summarize(series_of(records, &RealizationRecord::profile));
  if (!c.fit) return s;
  s.exponents = transport_exponents(c, s.t, s.m2.mean, s.m2_centroid.mean, s.ipr.mean);
  add_realization_errors(c, s.t, records, options.threads, *s.exponents);
  return s;
}

std::vector<std::string> notes(const TransportCase& c) {
  if (c.fit || !(c.fit_end > c.dynamics.integration.duration)) return {};
  return {"note: the fit window " + format_number(c.fit_begin) + ":" + format_number(c.fit_end) +
          " s reaches beyond T = " + format_number(c.dynamics.integration.duration) + " s; no exponents fitted"};
}

}  // namespace granular
