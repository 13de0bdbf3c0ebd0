// spreading: energy spreading from a single-site kick in one granular chain, or the means of an
// ensemble of them (SPEC §4). PREFIX.csv (t,m2,ipr,energy_error,m2_centroid) and PREFIX.json
// (parameters, exponents); optionally the final state, profile, forces, energy map, g(ν).
#include <cstdio>
#include <optional>
#include <string>

#include "common/chain_options.hpp"
#include "common/dynamics_options.hpp"
#include "common/metadata.hpp"
#include "common/mode_kick_options.hpp"
#include "common/output_paths.hpp"
#include "common/tool_main.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/io/hdf5_file.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/study/spreading_files.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "Energy spreading after a single-site kick in a (disordered) granular chain, integrated with SABA2C\n"
      "or another scheme. Writes PREFIX.csv (t,m2,ipr,energy_error,m2_centroid: m2 about the kicked bead and\n"
      "about the energy centroid) and PREFIX.json (parameters, gamma, eta). Beads count from 1. With\n"
      "--realizations R > 1: means over realizations 0..R-1 of --seed (PREFIX-sem.csv: standard errors;\n"
      "--profile: the averaged profile), checkpointed in PREFIX.checkpoint; --resume continues a killed run.\n"
      "--final-state, --forces-at, --energy-map and --spectrum always describe realization --realization.",
      "spreading"};
  tool::describe_common(app);
  tool::ChainOptions chain_options;
  chain_options.n = 2501;
  tool::DynamicsOptions dynamics;
  tool::ModeKickOptions mode_kick;
  std::string ic = "displacement", output = "spreading", final_state, forces_at, energy_map, spectrum_file;
  std::string spectrum_of = "displacement";
  long long realizations = 1, force_samples = 1000, map_samples = 500, map_stride = 1, spectrum_samples = 2000;
  bool profile = false, quiet = false, resume = false;
  int threads = 0;
  tool::add_chain_options(app, chain_options);
  app.add_option("--ic", ic, "initial condition: displacement | velocity | mode (a linear mode: --mode, --mode-khz)")
      ->capture_default_str();
  tool::add_dynamics_options(app, dynamics);
  tool::add_mode_kick_options(app, mode_kick);
  app.add_option("--realizations", realizations, "realizations to average (ensemble means and exponents)")
      ->capture_default_str();
  app.add_option("--threads", threads, "threads for the realizations (0 = all cores); results do not depend on it")
      ->capture_default_str();
  app.add_flag("--resume", resume, "continue an interrupted --realizations run with the same parameters");
  app.add_option("--output", output, "prefix: writes PREFIX.csv and PREFIX.json")->capture_default_str();
  app.add_option("--final-state", final_state, "CSV of site,u,v,energy at T");
  app.add_flag("--profile", profile,
               "also write PREFIX-profile.csv: site,energy,force at T (ensemble: site,energy,energy_se)");
  app.add_option("--forces-at", forces_at,
                 "beads (e.g. 601,631,661) whose force goes to PREFIX-forces.csv: t,site,force");
  app.add_option("--force-samples", force_samples, "uniform times of the force series")->capture_default_str();
  app.add_option("--energy-map", energy_map, "HDF5 file of E_n(t_k): datasets energy [time][column], t, site");
  app.add_option("--map-samples", map_samples, "uniform times of the energy map")->capture_default_str();
  app.add_option("--map-stride", map_stride, "beads summed into one map column")->capture_default_str();
  app.add_option("--spectrum", spectrum_file, "CSV of the spectral density: freq_khz,g");
  app.add_option("--spectrum-samples", spectrum_samples, "uniform samples of the series for the spectral density")
      ->capture_default_str();
  app.add_option("--spectrum-of", spectrum_of,
                 "displacement (the paper's g) | velocity (a permanent step in u adds a flat floor, not a 1/nu^2 tail)")
      ->capture_default_str();
  app.add_flag("--quiet", quiet, "no warnings or progress line on stderr");

  return tool::run(
      app, argc, argv,
      [&] {
        tool::Metadata meta("spreading", argc, argv);
        if (realizations < 1) throw InvalidInput("--realizations " + std::to_string(realizations) + ": must be >= 1");
        const bool ensemble = realizations > 1 || resume;
        if (ensemble && (!chain_options.config.empty() || !chain_options.radii.empty()))
          throw InvalidInput(
              "--realizations/--resume: an ensemble draws random chains; --config/--radii give one chain");
        if (threads < 0) throw InvalidInput("--threads " + std::to_string(threads) + ": must be >= 0");
        for (auto [name, value] : {std::pair{"--force-samples", force_samples},
                                   {"--map-samples", map_samples},
                                   {"--map-stride", map_stride},
                                   {"--spectrum-samples", spectrum_samples}})
          if (value < 1) throw InvalidInput(std::string(name) + " " + std::to_string(value) + ": must be >= 1");
        const tool::SelectedChain selected = tool::build_chain(chain_options);
        TransportCase c;
        tool::apply(chain_options, selected.chain.size(), c);
        c.beads = selected.beads;
        c.kick = parse_kick(ic);
        tool::apply(mode_kick, c);
        c.realizations = static_cast<std::size_t>(realizations);
        c.profile_realizations = profile ? c.realizations : 0;
        SpreadingConfig& d = c.dynamics;
        tool::apply(dynamics, c);
        c.fit = c.fit_end <= d.duration * (1 + 1e-12);  // a window beyond T: no exponents, a note
        for (long s : forces_at.empty() ? std::vector<long>{} : parse_integer_list(forces_at, "--forces-at")) {
          if (s < 1 || static_cast<std::size_t>(s) > c.n)
            throw InvalidInput("--forces-at " + std::to_string(s) + ": outside the chain of " + std::to_string(c.n) +
                               " beads");
          d.force_sites.push_back(static_cast<std::size_t>(s - 1));
        }
        d.force_samples = static_cast<std::size_t>(force_samples);
        d.map_samples = energy_map.empty() ? 0 : static_cast<std::size_t>(map_samples);
        d.map_stride = static_cast<std::size_t>(map_stride);
        d.spectrum_samples = spectrum_file.empty() ? 0 : static_cast<std::size_t>(spectrum_samples);
        d.spectrum_source = parse_spectrum_source(spectrum_of);
        validate(c);
        const std::string csv_path = output + ".csv", json_path = output + ".json", sem_path = output + "-sem.csv";
        const std::string profile_path = profile ? output + "-profile.csv" : "", checkpoint = output + ".checkpoint";
        const std::string forces_path = d.force_sites.empty() ? "" : output + "-forces.csv";
        tool::check_outputs({csv_path, json_path, final_state, energy_map, spectrum_file, profile_path, forces_path,
                             ensemble ? sem_path : "", ensemble ? checkpoint : ""},
                            "--output/--final-state/--energy-map/--spectrum");

        const bool single_outputs =
            !final_state.empty() || !d.force_sites.empty() || !energy_map.empty() || !spectrum_file.empty();
        std::optional<TransportSummary> summary;
        if (ensemble) {
          ProgressMeter progress(c.realizations, "spreading", quiet || !MpiContext::instance().root() ? 0 : -1);
          summary = run_transport_study(c, {threads, checkpoint, resume, &progress});
          progress.finish();
          if (!MpiContext::instance().root()) return;
        }
        const KickedChain kicked = kick(c, selected.chain);
        const SpreadingResult r = !ensemble || single_outputs
                                      ? run_spreading(selected.chain, kicked.initial, spreading_config(c))
                                      : SpreadingResult{};
        std::optional<TransportExponents> exponents = summary ? summary->exponents : std::nullopt;
        if (!summary && c.fit) exponents = transport_exponents(c, r.t, r.m2, r.m2_centroid, r.ipr);
        std::vector<std::string> notes = summary ? warnings(*summary, d) : std::vector<std::string>{};
        for (const auto& w : warnings(r, d)) notes.push_back(w);  // none from a run not made
        if (!c.fit) notes.push_back("note: --fit " + dynamics.fit + " reaches beyond --T; no exponents fitted");
        for (const auto& note : quiet ? std::vector<std::string>{} : notes)
          std::fprintf(stderr, "spreading: %s\n", note.c_str());

        std::vector<std::unique_ptr<AtomicFile>> files;
        const auto open = [&](const std::string& path) -> std::ostream& {
          return files.emplace_back(std::make_unique<AtomicFile>(path))->stream();
        };
        summary ? write_spreading_csv(open(csv_path), *summary) : write_spreading_csv(open(csv_path), r);
        if (summary) write_standard_errors_csv(open(sem_path), *summary);
        if (!final_state.empty()) write_final_state_csv(open(final_state), r);
        if (profile)
          summary ? write_profile_csv(open(profile_path), *summary) : write_profile_csv(open(profile_path), r);
        if (!forces_path.empty()) write_forces_csv(open(forces_path), r, d.force_sites);
        if (!spectrum_file.empty()) {
          write_spectrum_csv(open(spectrum_file), r);
          meta["spectrum"] = {{"file", spectrum_file},
                              {"of", to_string(d.spectrum_source)},
                              {"samples", spectrum_samples}};
        }
        if (!energy_map.empty()) {
          std::vector<double> sites;
          for (std::size_t k = 0; k < r.map_columns; ++k) sites.push_back(static_cast<double>(k * d.map_stride + 1));
          write_hdf5_atomically(energy_map, {{"energy", {r.map_t.size(), r.map_columns}, r.map_energy.data()},
                                             {"t", {r.map_t.size()}, r.map_t.data()},
                                             {"site", {sites.size()}, sites.data()}});
        }

        meta["parameters"] = describe(c);
        meta["parameters"]["chain"] = selected.description;
        if (c.kick == Kick::velocity && (!ensemble || !c.match_beta))
          meta["parameters"]["beta_m_s"] = kicked.beta;  // the β used
        if (c.kick == Kick::mode) meta["parameters"]["mode_used"] = to_json(kicked.mode);
        meta["seed"] = chain_options.seed;
        for (const char* key : {"gamma", "gamma_err", "gamma_real_err", "eta", "eta_err", "eta_real_err", "power_law"})
          meta[key] = nullptr;
        const nlohmann::json fitted = exponents ? to_json(*exponents, c.centre) : nlohmann::json::object();
        for (const auto& [key, value] : fitted.items()) meta[key.c_str()] = value;
        if (summary)
          meta["ensemble"] = {{"realizations", summary->realizations},
                              {"threads", threads},
                              {"mpi_ranks", MpiContext::instance().size()},
                              {"max_energy_error", summary->max_energy_error},
                              {"reached_walls", summary->reached_walls}};
        if (!summary || single_outputs)
          meta["run"] = {{"realization", chain_options.realization},
                         {"initial_energy_J", r.initial_energy},
                         {"max_energy_error", r.max_energy_error},
                         {"steps", r.steps},
                         {"bond_updates", r.bond_updates},
                         {"integration_s", r.seconds},
                         {"window_final", {r.window_begin + 1, r.window_end}},
                         {"wall_energy", r.wall_energy},
                         {"reached_walls", r.reached_walls}};
        meta["output"] = csv_path;
        meta.write(json_path);  // the JSON first, then the CSVs: never a CSV without its metadata
        for (auto& f : files) f->commit();
        if (ensemble) CheckpointLog::remove_all(checkpoint);
      },
      {{"spectrum_source", "--spectrum-of"}, {"near_khz", "--mode-khz"}, {"amplitude", "--alpha"}});
}
