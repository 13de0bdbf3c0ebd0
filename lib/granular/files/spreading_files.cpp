#include "granular/files/spreading_files.hpp"

#include <nlohmann/json.hpp>
#include "granular/io/csv_writer.hpp"
#include "granular/io/hdf5_file.hpp"
#include "granular/number_format.hpp"
#include "granular/parallel/mpi_context.hpp"

namespace granular {

namespace {

// The base columns, then `dissipated` (damping) and `mle` (tangent map) when the run has them.
void write_columns(std::ostream& out, const std::vector<double>& time,
                   std::initializer_list<const std::vector<double>*> base, const std::vector<double>& dissipated,
                   const std::vector<double>& mle) {
  std::vector<std::string> names = {"t", "m2", "ipr", "energy_error", "m2_centroid"};
  std::vector<const std::vector<double>*> columns(base);
  if (!dissipated.empty()) names.push_back("dissipated"), columns.push_back(&dissipated);
  if (!mle.empty()) names.push_back("mle"), columns.push_back(&mle);
  for (std::size_t j = 0; j < names.size(); ++j) out << (j ? "," : "") << names[j];
  out << '\n';
  for (std::size_t i = 0; i < time.size(); ++i) {
    out << format_number(time[i]);
    for (const auto* c : columns) out << ',' << format_number((*c)[i]);
    out << '\n';
  }
}

}  // namespace

void write_spreading_csv(std::ostream& out, const SpreadingResult& r) {
  write_columns(out, r.t, {&r.m2, &r.ipr, &r.energy_error, &r.m2_centroid}, r.dissipated, r.mle);
}

void write_spreading_csv(std::ostream& out, const TransportSummary& m) {
  write_columns(out, m.t, {&m.m2.mean, &m.ipr.mean, &m.energy_error.mean, &m.m2_centroid.mean}, {}, m.mle.mean);
}

void write_deviation_csv(std::ostream& out, const SpreadingResult& r) {
  CsvWriter t(out, {"t", "site", "share"});
  const std::size_t n = r.final_state.size();
  for (std::size_t k = 0; k < r.deviation_t.size(); ++k)
    for (std::size_t i = 0; i < n; ++i) t.row(r.deviation_t[k], i + 1, r.deviation[k * n + i]);
}

void write_lyapunov_csv(std::ostream& out, const SpreadingResult& r) {
  const LyapunovSeries& l = r.lyapunov;
  const std::size_t k = l.exponents.empty() ? 0 : l.exponents.front().size();
  std::vector<std::string> names{"t"};
  for (std::size_t j = 1; j <= k; ++j) names.push_back("lambda_" + std::to_string(j));
  for (std::size_t j = 2; j <= k; ++j) names.push_back("gali_" + std::to_string(j));
  if (k >= 2) names.push_back("sali");
  for (std::size_t j = 0; j < names.size(); ++j) out << (j ? "," : "") << names[j];
  out << '\n';
  for (std::size_t s = 0; s < l.time.size(); ++s) {
    out << format_number(l.time[s]);
    for (double x : l.exponents[s]) out << ',' << format_number(x);
    if (k >= 2) {
      for (double x : l.gali[s]) out << ',' << format_number(x);
      out << ',' << format_number(l.sali[s]);
    }
    out << '\n';
  }
}

void write_standard_errors_csv(std::ostream& out, const TransportSummary& m) {
  CsvWriter t(out, {"t", "m2_se", "ipr_se", "energy_error_se", "m2_centroid_se"});
  for (std::size_t i = 0; i < m.t.size(); ++i)
    t.row(m.t[i], m.m2.standard_error[i], m.ipr.standard_error[i], m.energy_error.standard_error[i],
          m.m2_centroid.standard_error[i]);
}

void write_final_state_csv(std::ostream& out, const SpreadingResult& r) {
  CsvWriter t(out, {"site", "u", "v", "energy"});
  for (std::size_t i = 0; i < r.final_state.size(); ++i)
    t.row(i + 1, r.final_state.u[i], r.final_state.v[i], r.final_energy[i]);
}

void write_profile_csv(std::ostream& out, const SpreadingResult& r) {
  CsvWriter t(out, {"site", "energy", "force"});
  for (std::size_t i = 0; i < r.final_energy.size(); ++i) t.row(i + 1, r.final_energy[i], r.final_force[i]);
}

void write_profile_csv(std::ostream& out, const TransportSummary& m) {
  CsvWriter t(out, {"site", "energy", "energy_se"});
  for (std::size_t i = 0; i < m.profile.mean.size(); ++i) t.row(i + 1, m.profile.mean[i], m.profile.standard_error[i]);
}

void write_forces_csv(std::ostream& out, const SpreadingResult& r, const std::vector<std::size_t>& sites) {
  CsvWriter t(out, {"t", "site", "force"});
  for (std::size_t k = 0; k < r.force_t.size(); ++k)
    for (std::size_t j = 0; j < sites.size(); ++j) t.row(r.force_t[k], sites[j] + 1, r.forces[j][k]);
}

void write_spectrum_csv(std::ostream& out, const SpreadingResult& r) {
  CsvWriter t(out, {"freq_khz", "g"});
  for (std::size_t j = 0; j < r.spectrum.size(); ++j) t.row(r.spectrum_khz[j], r.spectrum[j]);
}

std::unique_ptr<Hdf5File> write_energy_map(const std::string& path, const SpreadingResult& r, std::size_t stride) {
  return write_energy_map(path, r.map_t, r.map_energy, r.map_columns, stride);
}

std::unique_ptr<Hdf5File> write_energy_map(const std::string& path, const std::vector<double>& t,
                                           const std::vector<double>& energy, std::size_t columns, std::size_t stride) {
  std::vector<double> sites;
  for (std::size_t k = 0; k < columns; ++k) sites.push_back(static_cast<double>(k * stride + 1));
  auto file = std::make_unique<Hdf5File>(path);
  file->write("energy", energy.data(), t.size(), columns);
  file->write("t", t);
  file->write("site", sites);
  return file;
}

std::vector<double> covariant_rows(const CovariantVectors& clv) {
  std::vector<double> rows;
  for (const auto& sample : clv.vectors)
    for (const State& w : sample)
      rows.insert(rows.end(), w.u.begin(), w.u.end()), rows.insert(rows.end(), w.v.begin(), w.v.end());
  return rows;
}

namespace {
std::vector<double> flat(const std::vector<std::vector<double>>& table) {
  std::vector<double> all;
  for (const auto& row : table) all.insert(all.end(), row.begin(), row.end());
  return all;
}
}  // namespace

std::unique_ptr<Hdf5File> write_covariant_vectors(const std::string& path, const SpreadingResult& r,
                                                  const SpreadingRunConfig& config) {
  const CovariantVectors& c = r.covariant;
  const std::size_t samples = c.time.size(), k = c.growth_rates.size(), n = r.final_state.size();
  auto file = std::make_unique<Hdf5File>(path);
  file->write("t", c.time);
  const std::vector<double> rows = covariant_rows(c);
  file->write("vectors", rows.data(), samples * k, 2 * n);
  file->write("growth_rates", c.growth_rates);
  file->write("exponents", c.exponents);
  if (k >= 2) file->write("split_angles", flat(c.split_angles).data(), samples, k - 1);
  file->write("participation", flat(c.participation).data(), samples, k);
  file->write("centre", flat(c.centre).data(), samples, k);
  file->attribute("vectors_layout", "row s*k + i: CLV_{i+1} at sample s (t[s]); columns du_1..du_N, dv_1..dv_N; k = " +
                                        std::to_string(k) + ", N = " + std::to_string(n));
  file->attribute("vectors_units", "du dimensionless, dv [1/s]; unit norm in (du, t_unit dv), t_unit = " +
                                       format_number(config.integration.lyapunov.time_unit) + " s");
  file->attribute("units",
                  "t [s], growth_rates and exponents [1/s] over t[0]..t[-1], split_angles [rad], "
                  "participation [beads], centre [bead index, from 0]");
  return file;
}

nlohmann::json describe_covariant(const SpreadingResult& r, const SpreadingRunConfig& config, const std::string& file) {
  const CovariantVectorsConfig clv = covariant_config(config);
  const CovariantVectors& c = r.covariant;
  nlohmann::json j = {{"vectors", clv.vectors},
                      {"seed", clv.seed},
                      {"time_unit_s", clv.time_unit},
                      {"forward_transient_steps", clv.forward_transient},
                      {"backward_transient_steps", clv.backward_transient},
                      {"transient_s", static_cast<double>(clv.forward_transient) * config.integration.time_step},
                      {"samples", c.time.size()},
                      {"window_s",
                       c.time.empty() ? nlohmann::json(nullptr) : nlohmann::json({c.time.front(), c.time.back()})},
                      {"growth_rates_per_s", c.growth_rates},
                      {"exponents_per_s", c.exponents},
                      {"stored_bytes", c.stored_bytes}};
  if (!file.empty()) j["file"] = file;
  return j;
}

nlohmann::json describe_run(const SpreadingResult& r, const nlohmann::json& realization) {
  nlohmann::json run = {{"realization", realization},
                        {"initial_energy_J", r.initial_energy},
                        {"max_energy_error", r.max_energy_error},
                        {"steps", r.steps},
                        {"bond_updates", r.bond_updates},
                        {"integration_s", r.seconds},
                        {"window_final", {r.window_begin + 1, r.window_end}},
                        {"wall_energy", r.wall_energy},
                        {"reached_walls", r.reached_walls}};
  if (!r.dissipated.empty()) run["dissipated_J"] = r.dissipated.back();  // with damping only
  if (!r.mle.empty()) run["mle_per_s"] = r.mle.back();                   // with the tangent map only
  return run;
}

nlohmann::json describe_lyapunov(const SpreadingResult& r, const SpreadingRunConfig& config, const std::string& file) {
  const LyapunovSeries& l = r.lyapunov;
  nlohmann::json j = {{"vectors", l.exponents.empty() ? 0 : l.exponents.front().size()},
                      {"starting_vectors", "random orthonormal, norm (du, t_unit dv)"},
                      {"seed", lyapunov_spectrum_config(config).seed},
                      {"exponents_T_per_s",
                       l.exponents.empty() ? nlohmann::json(nullptr) : nlohmann::json(l.exponents.back())}};
  if (!l.sali.empty()) j["gali_T"] = l.gali.back(), j["sali_T"] = l.sali.back();
  if (!file.empty()) j["file"] = file;
  return j;
}

std::vector<std::string> SpreadingPaths::all() const {
  return {csv,    json, final_state, energy_map, spectrum, profile,
          forces, sem,  checkpoint,  deviation,  lyapunov, covariant};
}

SpreadingPaths spreading_paths(const std::string& prefix, bool ensemble, bool profile, bool forces, bool lyapunov,
                               bool covariant) {
  SpreadingPaths p;
  if (covariant) p.covariant = prefix + "-clv.h5";
  if (lyapunov) p.lyapunov = prefix + "-lyapunov.csv";
  p.csv = prefix + ".csv", p.json = prefix + ".json";
  if (ensemble) p.sem = prefix + "-sem.csv", p.checkpoint = prefix + ".checkpoint";
  if (profile) p.profile = prefix + "-profile.csv";
  if (forces) p.forces = prefix + "-forces.csv";
  return p;
}

void SpreadingFiles::commit() {
  for (auto& f : text) f->commit();
  if (energy_map) energy_map->commit();
  if (covariant) covariant->commit();
}

SpreadingFiles write_spreading_files(const SpreadingPaths& paths, const SpreadingResult& run,
                                     const TransportSummary* ensemble, const SpreadingRunConfig& config) {
  SpreadingFiles files;
  const auto open = [&](const std::string& path) -> std::ostream& {
    return files.text.emplace_back(std::make_unique<AtomicFile>(path))->stream();
  };
  ensemble ? write_spreading_csv(open(paths.csv), *ensemble) : write_spreading_csv(open(paths.csv), run);
  if (ensemble) write_standard_errors_csv(open(paths.sem), *ensemble);
  if (!paths.profile.empty())
    ensemble ? write_profile_csv(open(paths.profile), *ensemble) : write_profile_csv(open(paths.profile), run);
  if (!paths.forces.empty()) write_forces_csv(open(paths.forces), run, config.forces.sites);
  if (!paths.final_state.empty()) write_final_state_csv(open(paths.final_state), run);
  if (!paths.spectrum.empty()) write_spectrum_csv(open(paths.spectrum), run);
  if (!paths.energy_map.empty())
    files.energy_map = write_energy_map(paths.energy_map, run, config.energy_map ? config.energy_map->stride : 1);
  if (!paths.deviation.empty()) write_deviation_csv(open(paths.deviation), run);
  if (!paths.lyapunov.empty()) write_lyapunov_csv(open(paths.lyapunov), run);
  if (!paths.covariant.empty()) files.covariant = write_covariant_vectors(paths.covariant, run, config);
  return files;
}

std::vector<std::string> spreading_notes(const TransportCase& c, const SpreadingResult& run,
                                         const TransportSummary* ensemble) {
  std::vector<std::string> all = ensemble ? warnings(*ensemble, c.dynamics) : std::vector<std::string>{};
  for (const auto& w : warnings(run, c.dynamics)) all.push_back(w);
  for (const auto& note : notes(c)) all.push_back(note);
  return all;
}

nlohmann::json describe_ensemble(const TransportSummary& summary, int threads) {
  return {{"realizations", summary.realizations},       {"threads", threads},
          {"mpi_ranks", MpiContext::instance().size()}, {"max_energy_error", summary.max_energy_error},
          {"reached_walls", summary.reached_walls},     {"failed_excluded", summary.excluded}};
}

nlohmann::json describe_spectral_density(const SpectralDensityObserver::Settings& settings) {
  return {{"of", to_string(settings.source)}, {"samples", settings.samples}};
}

nlohmann::json describe_parameters(const TransportCase& c, const nlohmann::json& chain, const KickedChain& kicked,
                                   bool ensemble) {
  nlohmann::json parameters = describe(c);
  parameters["chain"] = chain;
  if (c.kick == Kick::velocity && (!ensemble || c.beta)) parameters["beta_used"] = kicked.beta;  // the β used
  if (c.kick == Kick::mode) parameters["mode_used"] = to_json(kicked.mode);
  return parameters;
}

nlohmann::json describe_exponents(const std::optional<TransportExponents>& exponents, SpreadCentre shown) {
  nlohmann::json entries;
  for (const char* key : {"gamma", "gamma_err", "gamma_real_err", "eta", "eta_err", "eta_real_err", "power_law"})
    entries[key] = nullptr;
  if (exponents) entries.update(to_json(*exponents, shown));
  return entries;
}

nlohmann::json describe_spreading(const SpreadingDescription& d) {
  const bool ensemble = d.ensemble != nullptr;
  nlohmann::json j;
  j["parameters"] = describe_parameters(d.c, d.chain, d.kicked, ensemble);
  j["seed"] = d.c.chain.seed;
  if (!d.resumed.is_null()) j["resumed_checkpoint"] = d.resumed;
  j["time_step_rule"] = d.step_rule;
  j.update(describe_exponents(d.exponents, d.c.centre));
  if (ensemble) j["ensemble"] = describe_ensemble(*d.ensemble, d.threads);
  if (d.run == nullptr) return j;
  const SpreadingRunConfig& config = d.c.dynamics;
  const auto file = [&](std::string SpreadingPaths::*path) { return d.paths ? d.paths->*path : std::string(); };
  j["run"] = describe_run(*d.run, d.realization);
  if (config.spectrum) {
    j["spectrum"] = describe_spectral_density(*config.spectrum);
    if (const std::string f = file(&SpreadingPaths::spectrum); !f.empty()) j["spectrum"]["file"] = f;
  }
  if (config.lyapunov_vectors > 0)
    j["lyapunov_spectrum"] = describe_lyapunov(*d.run, config, file(&SpreadingPaths::lyapunov));
  if (config.covariant_vectors > 0)
    j["covariant_vectors"] = describe_covariant(*d.run, config, file(&SpreadingPaths::covariant));
  return j;
}

}  // namespace granular
