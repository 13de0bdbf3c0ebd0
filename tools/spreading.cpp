// spreading: energy spreading from a single-site kick in one granular chain (SPEC §4).
// Writes PREFIX.csv (t,m2,ipr,energy_error) and PREFIX.json (parameters, exponents, run info);
// optionally the final state, the energy/force profile, force series, an HDF5 energy map and
// the spectral density.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "common/chain_options.hpp"
#include "common/metadata.hpp"
#include "common/tool_main.hpp"
#include "granular/analysis/power_law_fit.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/spreading.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/csv_writer.hpp"
#include "granular/io/hdf5_file.hpp"
#include "granular/number_format.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/study/transport_study.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{"Energy spreading after a single-site kick in a (disordered) granular chain, integrated with SABA2C\n"
               "or another scheme. Writes PREFIX.csv (t,m2,ipr,energy_error) and PREFIX.json. Beads count from 1.\n"
               "With --realizations R > 1: means over realizations 0..R-1 of --seed (PREFIX-sem.csv: standard errors;\n"
               "--profile: the averaged profile), checkpointed in PREFIX.checkpoint; --resume continues a killed run.\n"
               "--final-state, --forces-at, --energy-map and --spectrum always describe realization --realization.",
               "spreading"};
  tool::describe_common(app);
  tool::ChainOptions chain_options;
  chain_options.n = 2501;
  std::string ic = "displacement", beta_text = "match", force_law = "hertz";
  std::string integrator = "saba2c", sampling = "log", fit_text = "4e-3:1e-2", output = "spreading", final_state;
  std::string forces_at, energy_map, spectrum_file, active_window = "on";
  long long realizations = 1, site = 0, samples = 200, force_samples = 1000;
  long long map_samples = 500, map_stride = 1, spectrum_samples = 2000;
  double alpha = 1e-7, duration = 1e-2, dt = 1e-6;
  PowerLawCriterion criterion;
  double window_threshold = 1e-30, reference_max_step = 0.01e-6;
  bool profile = false, quiet = false, resume = false;
  std::string energy_guard = "stop";
  double max_energy_error = 1e-3;
  int threads = 0;
  tool::add_chain_options(app, chain_options);
  app.add_option("--realizations", realizations, "realizations to average (ensemble means and exponents)")->capture_default_str();
  app.add_option("--threads", threads, "threads for the realizations (0 = all cores); results do not depend on it")->capture_default_str();
  app.add_flag("--resume", resume, "continue an interrupted --realizations run with the same parameters");
  app.add_option("--ic", ic, "initial condition: displacement | velocity")->capture_default_str();
  app.add_option("--alpha", alpha, "displacement kick [m] (also what --beta match matches)")->capture_default_str();
  app.add_option("--beta", beta_text, "velocity kick [m/s], or 'match': the energy of --alpha on this chain")->capture_default_str();
  app.add_option("--site", site, "kicked bead, 1..N (default the centre, (N+1)/2)");
  app.add_option("--T", duration, "duration [s], a whole number of --dt")->capture_default_str();
  app.add_option("--dt", dt, "time step tau [s]")->capture_default_str();
  app.add_option("--force-law", force_law, "hertz | fpu | linear")->capture_default_str();
  app.add_option("--integrator", integrator, "saba2c | saba2 | aba864 | srkn14a | reference (Odeint RKF78)")->capture_default_str();
  app.add_option("--samples", samples, "sample times of t,m2,ipr,energy_error")->capture_default_str();
  app.add_option("--sampling", sampling, "log (tau..T) | uniform (0..T)")->capture_default_str();
  app.add_option("--fit", fit_text, "fit range start:stop [s] for gamma (m2 ~ t^gamma) and eta (ipr ~ t^-eta)")->capture_default_str();
  app.add_option("--kappa", criterion.kappa, "'not a power law' when |L_d - gamma| >= kappa after the fit start")->capture_default_str();
  app.add_option("--output", output, "prefix: writes PREFIX.csv and PREFIX.json")->capture_default_str();
  app.add_option("--final-state", final_state, "CSV of site,u,v,energy at T");
  app.add_flag("--profile", profile, "also write PREFIX-profile.csv: site,energy,force at T");
  app.add_option("--forces-at", forces_at, "beads (e.g. 601,631,661) whose force goes to PREFIX-forces.csv: t,site,force");
  app.add_option("--force-samples", force_samples, "uniform times of the force series")->capture_default_str();
  app.add_option("--energy-map", energy_map, "HDF5 file of E_n(t_k): datasets energy [time][column], t, site");
  app.add_option("--map-samples", map_samples, "uniform times of the energy map")->capture_default_str();
  app.add_option("--map-stride", map_stride, "beads summed into one map column")->capture_default_str();
  app.add_option("--spectrum", spectrum_file, "CSV of the spectral density: freq_khz,g");
  app.add_option("--spectrum-samples", spectrum_samples, "uniform samples of u_n(t) for the spectral density")->capture_default_str();
  app.add_option("--active-window", active_window, "on | off: integrate only where the wave has arrived")->capture_default_str();
  app.add_option("--window-threshold", window_threshold, "relative kinetic energy that grows the window")->capture_default_str();
  app.add_option("--reference-max-step", reference_max_step, "largest step of --integrator reference [s], 0 = none")->capture_default_str();
  app.add_option("--max-energy-error", max_energy_error, "guard: relative energy error that stops (or is reported), 0 = off")->capture_default_str();
  app.add_option("--energy-guard", energy_guard, "stop | warn: what passing --max-energy-error does")->capture_default_str();
  app.add_flag("--quiet", quiet, "no warnings or progress line on stderr");

  return tool::run(app, argc, argv, [&] {
    tool::Metadata meta("spreading", argc, argv);
    if (realizations < 1) throw InvalidInput("--realizations " + std::to_string(realizations) + ": must be >= 1");
    const bool ensemble = realizations > 1 || resume;
    if (ensemble && (!chain_options.config.empty() || !chain_options.radii.empty()))
      throw InvalidInput("--realizations/--resume: an ensemble draws random chains; --config/--radii give one chain");
    if (threads < 0) throw InvalidInput("--threads " + std::to_string(threads) + ": must be >= 0");
    if (ic != "displacement" && ic != "velocity") throw InvalidInput("--ic '" + ic + "': expected displacement or velocity");
    if (active_window != "on" && active_window != "off") throw InvalidInput("--active-window '" + active_window + "': on or off");
    for (auto [name, value] : {std::pair{"--samples", samples}, {"--force-samples", force_samples},
                               {"--map-samples", map_samples}, {"--map-stride", map_stride},
                               {"--spectrum-samples", spectrum_samples}})
      if (value < 1) throw InvalidInput(std::string(name) + " " + std::to_string(value) + ": must be >= 1");
    const tool::SelectedChain selected = tool::build_chain(chain_options);
    const Chain& chain = selected.chain;
    const std::size_t beads = chain.size();

    SpreadingConfig config;
    config.force_law = parse_force_law(force_law);
    config.integrator = integrator;
    if (integrator != "reference") {
      try {
        parse_scheme(integrator);
      } catch (const InvalidInput&) {
        throw InvalidInput("--integrator '" + integrator + "': expected saba2c, saba2, aba864, srkn14a or reference");
      }
    }
    config.duration = duration;
    config.time_step = dt;
    config.samples = static_cast<std::size_t>(samples);
    config.sampling = parse_sampling(sampling);
    config.window.enabled = active_window == "on";
    config.window.threshold = window_threshold;
    if (!(reference_max_step >= 0) || !std::isfinite(reference_max_step))
      throw InvalidInput("--reference-max-step " + format_number(reference_max_step) + ": must be finite and >= 0");
    if (!(window_threshold >= 0) || !std::isfinite(window_threshold))
      throw InvalidInput("--window-threshold " + format_number(window_threshold) + ": must be finite and >= 0");
    config.reference.max_step = reference_max_step;
    if (!forces_at.empty())
      for (long s : parse_integer_list(forces_at, "--forces-at")) {
        if (s < 1 || static_cast<std::size_t>(s) > beads)
          throw InvalidInput("--forces-at " + std::to_string(s) + ": outside the chain of " + std::to_string(beads) + " beads");
        config.force_sites.push_back(static_cast<std::size_t>(s - 1));
      }
    config.force_samples = static_cast<std::size_t>(force_samples);
    config.map_samples = energy_map.empty() ? 0 : static_cast<std::size_t>(map_samples);
    config.map_stride = static_cast<std::size_t>(map_stride);
    config.spectrum_samples = spectrum_file.empty() ? 0 : static_cast<std::size_t>(spectrum_samples);
    if (!(max_energy_error >= 0) || !std::isfinite(max_energy_error))
      throw InvalidInput("--max-energy-error " + format_number(max_energy_error) + ": must be finite and >= 0");
    if (energy_guard != "stop" && energy_guard != "warn") throw InvalidInput("--energy-guard '" + energy_guard + "': stop or warn");
    config.max_energy_error = max_energy_error;
    config.stop_on_energy_error = energy_guard == "stop";
    validate(config, beads);

    std::string fit_list = fit_text;  // start:stop is two numbers here, not a range to expand
    for (char& c : fit_list)
      if (c == ':') c = ',';
    const std::vector<double> fit_range = parse_number_list(fit_list, "--fit", 0, 2);
    if (fit_range.size() != 2 || !(fit_range[0] > 0) || !(fit_range[1] > fit_range[0]))
      throw InvalidInput("--fit '" + fit_text + "': expected start:stop with 0 < start < stop");
    if (!(criterion.kappa > 0) || !std::isfinite(criterion.kappa))
      throw InvalidInput("--kappa " + format_number(criterion.kappa) + ": must be finite and > 0");
    criterion.t_start = fit_range[0];

    const bool site_given = app.count("--site") > 0;
    if (site_given && (site < 1 || site > static_cast<long long>(beads)))
      throw InvalidInput("--site " + std::to_string(site) + ": outside the chain of " + std::to_string(beads) + " beads (1..N)");
    const std::size_t kicked = site_given ? static_cast<std::size_t>(site - 1) : centre_site(beads);
    const ForceLaw law = make_force_law(config.force_law, chain);
    State initial;
    double beta = 0;
    if (ic == "displacement") {
      initial = displacement_kick(chain, kicked, alpha);
    } else {
      if (beta_text == "match") {
        beta = matched_velocity(law, chain, kicked, alpha);
      } else {
        const auto b = parse_number_list(beta_text, "--beta", 0, 1);
        if (b.size() != 1) throw InvalidInput("--beta '" + beta_text + "': one number or 'match'");
        beta = b[0];
      }
      initial = velocity_kick(chain, kicked, beta);
    }

    const bool fit_possible = fit_range[1] <= duration * (1 + 1e-12);
    if (fit_possible) {
      // A fit that cannot work is bad input, found before the run rather than after it.
      std::vector<double> times;
      const auto steps = sample_steps(static_cast<std::uint64_t>(std::llround(duration / dt)), config.samples, config.sampling);
      for (auto s : steps) times.push_back(static_cast<double>(s) * dt);
      try {
        windowed_exponent(times, times, fit_range[0], fit_range[1]);
      } catch (const InvalidInput& e) {
        throw InvalidInput("--fit " + fit_text + ": too few --samples in a sub-window (" + e.what() + ")");
      }
    }

    // Every output is checked before the run and written only after it.
    const std::string csv_path = output + ".csv", json_path = output + ".json";
    const std::string profile_path = output + "-profile.csv", forces_path = output + "-forces.csv";
    for (const std::string* path : std::initializer_list<const std::string*>{&csv_path, &json_path, &final_state, &energy_map, &spectrum_file})
      if (!path->empty()) check_writable(*path);
    {
      std::vector<std::string> paths = {csv_path, json_path};
      for (const std::string& p : {final_state, energy_map, spectrum_file})
        if (!p.empty()) paths.push_back(p);
      if (profile) paths.push_back(profile_path);
      if (!config.force_sites.empty()) paths.push_back(forces_path);
      for (std::size_t i = 0; i < paths.size(); ++i)
        for (std::size_t j = i + 1; j < paths.size(); ++j)
          if (std::filesystem::absolute(paths[i]).lexically_normal() == std::filesystem::absolute(paths[j]).lexically_normal())
            throw InvalidInput("--output/--final-state/--energy-map/--spectrum: two outputs would both be " + paths[i]);
    }
    if (profile) check_writable(profile_path);
    if (!config.force_sites.empty()) check_writable(forces_path);

    const std::string sem_path = output + "-sem.csv", checkpoint = output + ".checkpoint";
    if (ensemble) {
      check_writable(sem_path);
      check_writable(checkpoint);
    }
    // Realization --realization alone answers the single-chain outputs; an ensemble needs it
    // only for those.
    const bool single_outputs = !final_state.empty() || !config.force_sites.empty() || !energy_map.empty() ||
                                !spectrum_file.empty();
    std::optional<TransportSummary> summary;
    if (ensemble) {
      TransportCase c;
      c.disorder = parse_disorder(chain_options.disorder);
      c.q = chain_options.q;
      c.xi = chain_options.xi;
      c.n = beads;
      c.precompression = chain_options.f0;
      c.r1 = chain_options.r1;
      c.kick = parse_kick(ic);
      c.alpha = alpha;
      c.beta = beta;
      c.match_beta = ic == "velocity" && beta_text == "match";
      c.site = kicked;
      c.dynamics = config;
      c.seed = static_cast<std::uint64_t>(chain_options.seed);
      c.realizations = static_cast<std::size_t>(realizations);
      c.profile_realizations = profile ? c.realizations : 0;
      c.fit = fit_possible;
      c.fit_begin = fit_range[0];
      c.fit_end = fit_range[1];
      c.criterion = criterion;
      const MpiContext& mpi = MpiContext::instance();
      ProgressMeter progress(c.realizations, "spreading", quiet || !mpi.root() ? 0 : -1);
      summary = run_transport_study(c, {threads, checkpoint, resume, &progress});
      progress.finish();
      if (!mpi.root()) return;
    }
    const SpreadingResult r = !ensemble || single_outputs ? run_spreading(chain, initial, config) : SpreadingResult{};

    nlohmann::json fit = nullptr;
    if (fit_possible && summary) {
      const PowerLawAnalysis& g = summary->gamma;
      const PowerLawAnalysis& e = summary->eta;
      fit = {{"gamma", g.exponent.value}, {"gamma_err", g.exponent.error}, {"eta", e.exponent.value},
             {"eta_err", e.exponent.error}, {"power_law", g.verdict.power_law},
             {"max_log_derivative_deviation", g.verdict.worst_deviation}};
    } else if (fit_possible) {
      const PowerLawAnalysis g = analyze_power_law(r.t, r.m2, fit_range[0], fit_range[1], criterion);
      std::vector<double> inverse_ipr;
      for (double p : r.ipr) inverse_ipr.push_back(1 / p);  // P⁻¹ ∝ t^−η  ⇔  1/P⁻¹ ∝ t^η
      const ExponentEstimate e = windowed_exponent(r.t, inverse_ipr, fit_range[0], fit_range[1]);
      fit = {{"gamma", g.exponent.value}, {"gamma_err", g.exponent.error}, {"eta", e.value}, {"eta_err", e.error},
             {"power_law", g.verdict.power_law}, {"max_log_derivative_deviation", g.verdict.worst_deviation}};
    } else if (!quiet) {
      std::fprintf(stderr, "spreading: note: --fit %s reaches beyond --T; no exponents fitted\n", fit_text.c_str());
    }
    if (r.reached_walls && !quiet)
      std::fprintf(stderr, "spreading: warning: energy reached the walls ((E_1 + E_N)/H0 up to %s): the chain is too short for T\n",
                   format_number(r.wall_energy).c_str());
    if (r.energy_guard_time >= 0 && !quiet)
      std::fprintf(stderr, "spreading: warning: relative energy error passed --max-energy-error %s at t = %s s\n",
                   format_number(max_energy_error).c_str(), format_number(r.energy_guard_time).c_str());
    if (summary && summary->max_energy_error > max_energy_error && max_energy_error > 0 && !quiet)
      std::fprintf(stderr, "spreading: warning: relative energy error reached %s, past --max-energy-error %s\n",
                   format_number(summary->max_energy_error).c_str(), format_number(max_energy_error).c_str());
    if (summary && summary->reached_walls > 0 && !quiet)
      std::fprintf(stderr, "spreading: warning: energy reached the walls in %zu of %zu realizations: the chain is too short for T\n",
                   summary->reached_walls, summary->realizations);

    AtomicFile csv(csv_path);
    std::optional<AtomicFile> state_file, profile_file, forces_file, spectrum_out, sem_file;
    if (summary) {
      const TransportSummary& m = *summary;
      CsvWriter table(csv.stream(), {"t", "m2", "ipr", "energy_error"});
      for (std::size_t i = 0; i < m.t.size(); ++i) table.row(m.t[i], m.m2.mean[i], m.ipr.mean[i], m.energy_error.mean[i]);
      sem_file.emplace(sem_path);
      CsvWriter sem(sem_file->stream(), {"t", "m2_se", "ipr_se", "energy_error_se"});
      for (std::size_t i = 0; i < m.t.size(); ++i)
        sem.row(m.t[i], m.m2.standard_error[i], m.ipr.standard_error[i], m.energy_error.standard_error[i]);
    } else {
      CsvWriter table(csv.stream(), {"t", "m2", "ipr", "energy_error"});
      for (std::size_t i = 0; i < r.t.size(); ++i) table.row(r.t[i], r.m2[i], r.ipr[i], r.energy_error[i]);
    }
    if (!final_state.empty()) {
      state_file.emplace(final_state);
      CsvWriter t(state_file->stream(), {"site", "u", "v", "energy"});
      for (std::size_t i = 0; i < beads; ++i) t.row(i + 1, r.final_state.u[i], r.final_state.v[i], r.final_energy[i]);
    }
    if (profile && summary) {
      profile_file.emplace(profile_path);
      CsvWriter t(profile_file->stream(), {"site", "energy", "energy_se"});
      for (std::size_t i = 0; i < beads; ++i) t.row(i + 1, summary->profile.mean[i], summary->profile.standard_error[i]);
    } else if (profile) {
      profile_file.emplace(profile_path);
      CsvWriter t(profile_file->stream(), {"site", "energy", "force"});
      for (std::size_t i = 0; i < beads; ++i) t.row(i + 1, r.final_energy[i], r.final_force[i]);
    }
    if (!config.force_sites.empty()) {
      forces_file.emplace(forces_path);
      CsvWriter t(forces_file->stream(), {"t", "site", "force"});
      for (std::size_t k = 0; k < r.force_t.size(); ++k)
        for (std::size_t j = 0; j < config.force_sites.size(); ++j)
          t.row(r.force_t[k], config.force_sites[j] + 1, r.forces[j][k]);
    }
    if (!spectrum_file.empty()) {
      spectrum_out.emplace(spectrum_file);
      CsvWriter t(spectrum_out->stream(), {"freq_khz", "g"});
      for (std::size_t j = 0; j < r.spectrum.size(); ++j) t.row(r.spectrum_khz[j], r.spectrum[j]);
    }
    if (!energy_map.empty()) {
      std::vector<double> sites;
      for (std::size_t c = 0; c < r.map_columns; ++c) sites.push_back(static_cast<double>(c * config.map_stride + 1));
      write_hdf5_atomically(energy_map, {{"energy", {r.map_t.size(), r.map_columns}, r.map_energy.data()},
                                         {"t", {r.map_t.size()}, r.map_t.data()},
                                         {"site", {sites.size()}, sites.data()}});
    }

    meta["parameters"] = {
        {"chain", selected.description}, {"realizations", realizations},
        {"ic", ic}, {"site", kicked + 1}, {"alpha_m", ic == "displacement" ? alpha : 0.0}, {"beta_m_s", beta},
        {"beta_matched", ic == "velocity" && beta_text == "match"},
        {"T_s", duration}, {"dt_s", dt}, {"force_law", to_string(config.force_law)}, {"integrator", integrator},
        {"samples", samples}, {"sampling", sampling}, {"fit_s", fit_range}, {"kappa", criterion.kappa},
        {"t_star_s", criterion.t_start}, {"active_window", active_window}, {"window_threshold", window_threshold},
        {"reference_max_step_s", reference_max_step}};
    meta["seed"] = chain_options.seed;
    if (fit.is_null()) {
      for (const char* key : {"gamma", "gamma_err", "eta", "eta_err", "power_law"}) meta[key] = nullptr;
    } else {
      for (const char* key : {"gamma", "gamma_err", "eta", "eta_err", "power_law"}) meta[key] = fit[key];
      meta["max_log_derivative_deviation"] = fit["max_log_derivative_deviation"];
    }
    if (summary) {
      meta["ensemble"] = {{"realizations", summary->realizations}, {"threads", threads},
                          {"mpi_ranks", MpiContext::instance().size()}, {"max_energy_error", summary->max_energy_error},
                          {"reached_walls", summary->reached_walls}, {"eta_power_law", summary->eta.verdict.power_law}};
    }
    if (!summary || single_outputs)
      meta["run"] = {{"realization", chain_options.realization}, {"initial_energy_J", r.initial_energy},
                     {"max_energy_error", r.max_energy_error}, {"steps", r.steps}, {"bond_updates", r.bond_updates},
                     {"integration_s", r.seconds}, {"window_final", {r.window_begin + 1, r.window_end}},
                     {"wall_energy", r.wall_energy}, {"reached_walls", r.reached_walls}};
    meta["output"] = csv_path;
    csv.commit();
    for (auto* f : {&state_file, &profile_file, &forces_file, &spectrum_out, &sem_file})
      if (*f) (*f)->commit();
    meta.write(json_path);
    if (ensemble) CheckpointLog::remove_all(checkpoint);
  });
}
