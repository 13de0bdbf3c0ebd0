// spreading: energy spreading from a single-site kick in one granular chain, or the means of an
// ensemble of them (SPEC §4). PREFIX.csv (t,m2,ipr,energy_error,m2_centroid) and PREFIX.json
// (parameters, exponents); optionally the final state, profile, forces, energy map, g(ν).
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "common/kicked_case.hpp"
#include "common/long_run_options.hpp"
#include "common/metadata.hpp"
#include "common/output_paths.hpp"
#include "common/spreading_outputs.hpp"
#include "common/tool_main.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
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
  tool::KickedCaseOptions options;
  const tool::DynamicsOptions& dynamics = options.dynamics;
  std::string output = "spreading";
  tool::LongRunOptions run;
  tool::SpreadingOutputs more;
  tool::add_kicked_case_options(app, options);
  tool::add_long_run_options(app, run);
  tool::add_output_option(app, output);
  tool::add_spreading_outputs(app, more);

  return tool::run(
      app, argc, argv,
      [&] {
        tool::Metadata meta("spreading", argc, argv);
        const bool ensemble = options.realizations > 1 || run.resuming();
        if (run.threads < 0) throw InvalidInput("--threads " + std::to_string(run.threads) + ": must be >= 0");
        tool::KickedCase k = tool::kicked_case(options, ensemble);
        const tool::SelectedChain& selected = k.selected;
        TransportCase& c = k.c;
        c.profile_realizations = more.profile ? c.realizations : 0;
        const SpreadingConfig& d = c.dynamics;
        tool::apply(more, c);
        const nlohmann::json step_rule = tool::settle(c, options, app.count("--dt") > 0);
        const std::string csv_path = output + ".csv", json_path = output + ".json", sem_path = output + "-sem.csv";
        const std::string profile_path = more.profile ? output + "-profile.csv" : "",
                          checkpoint = output + ".checkpoint";
        const std::string forces_path = d.force_sites.empty() ? "" : output + "-forces.csv";
        const tool::OutputClaim claim(output, meta.command(),
                                      ensemble ? std::optional(run.checkpoints()) : std::nullopt);
        tool::check_outputs({csv_path, json_path, more.final_state, more.energy_map, more.spectrum, profile_path,
                             forces_path, ensemble ? sem_path : "", ensemble ? checkpoint : "",
                             dynamics.beyond.deviation},
                            "--output/--final-state/--energy-map/--spectrum");
        const bool single = more.single() || !dynamics.beyond.deviation.empty();  // a run of its own

        // Read before the run: resuming rewrites the checkpoint under this code's name.
        const nlohmann::json resumed = ensemble ? tool::resumed_code(run, {checkpoint}) : nullptr;
        std::optional<TransportSummary> summary;
        if (ensemble) {
          summary = tool::run_ensemble(c, run, checkpoint, "spreading", argc, argv);
          if (!MpiContext::instance().root()) return;
        }
        const KickedChain kicked = kick(c, selected.chain);
        const SpreadingResult r =
            !ensemble || single ? run_spreading(selected.chain, kicked.initial, spreading_config(c)) : SpreadingResult{};
        std::optional<TransportExponents> exponents = summary ? summary->exponents : std::nullopt;
        if (!summary && c.fit) exponents = transport_exponents(c, r.t, r.m2, r.m2_centroid, r.ipr);
        std::vector<std::string> notes = summary ? warnings(*summary, d) : std::vector<std::string>{};
        for (const auto& w : warnings(r, d)) notes.push_back(w);  // none from a run not made
        for (const auto& note : granular::notes(c)) notes.push_back(note);
        for (const auto& note : run.quiet ? std::vector<std::string>{} : notes)
          std::fprintf(stderr, "spreading: %s\n", note.c_str());

        std::vector<std::unique_ptr<AtomicFile>> files;
        const auto open = [&](const std::string& path) -> std::ostream& {
          return files.emplace_back(std::make_unique<AtomicFile>(path))->stream();
        };
        summary ? write_spreading_csv(open(csv_path), *summary) : write_spreading_csv(open(csv_path), r);
        if (summary) write_standard_errors_csv(open(sem_path), *summary);
        if (more.profile)
          summary ? write_profile_csv(open(profile_path), *summary) : write_profile_csv(open(profile_path), r);
        if (!forces_path.empty()) write_forces_csv(open(forces_path), r, d.force_sites);
        tool::write_single(more, r, d, open, meta);
        if (single && !dynamics.beyond.deviation.empty()) write_deviation_csv(open(dynamics.beyond.deviation), r);

        meta["parameters"] = describe(c);
        meta["parameters"]["chain"] = selected.description;
        if (c.kick == Kick::velocity && (!ensemble || !c.match_beta))
          meta["parameters"]["beta_m_s"] = kicked.beta;  // the β used
        if (c.kick == Kick::mode) meta["parameters"]["mode_used"] = to_json(kicked.mode);
        meta["seed"] = c.chain.seed;
        if (!resumed.is_null()) meta["resumed_checkpoint"] = resumed;
        meta["time_step_rule"] = step_rule;
        for (const char* key : {"gamma", "gamma_err", "gamma_real_err", "eta", "eta_err", "eta_real_err", "power_law"})
          meta[key] = nullptr;
        const nlohmann::json fitted = exponents ? to_json(*exponents, c.centre) : nlohmann::json::object();
        for (const auto& [key, value] : fitted.items()) meta[key.c_str()] = value;
        if (summary)
          meta["ensemble"] = {{"realizations", summary->realizations},
                              {"threads", run.threads},
                              {"failed_excluded", tool::report_excluded(c, *summary, meta, run, "spreading", argv[0])},
                              {"mpi_ranks", MpiContext::instance().size()},
                              {"max_energy_error", summary->max_energy_error},
                              {"reached_walls", summary->reached_walls}};
        if (!summary || single) meta["run"] = describe_run(r, options.chain.realization);
        meta["output"] = csv_path;
        meta.write(json_path);  // the JSON first, then the CSVs: never a CSV without its metadata
        for (auto& f : files) f->commit();
        if (ensemble) CheckpointLog::remove_all(checkpoint);
      },
      {{"spectrum_source", "--spectrum-of"},
       {"lyapunov", "--mle"},
       {"near_khz", "--mode-khz"},
       {"amplitude", "--alpha"}});
}
