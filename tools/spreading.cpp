// spreading: energy spreading from a single-site kick in one granular chain, or the means of an
// ensemble of them (docs/physics.md, "Nonlinear dynamics"). PREFIX.csv (t,m2,ipr,energy_error,m2_centroid) and
// PREFIX.json (parameters, exponents); optionally the final state, profile, forces, energy map, g(ν).
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "common/kicked_case.hpp"
#include "common/long_run_options.hpp"
#include "common/outputs.hpp"
#include "common/spreading_outputs.hpp"
#include "common/tool_main.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/files/spreading_files.hpp"
#include "granular/io/hdf5_file.hpp"
#include "granular/parallel/mpi_context.hpp"

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
  std::string output = "spreading";
  tool::LongRunOptions run;
  tool::SpreadingOutputs more;
  tool::add_kicked_case_options(app, options);
  tool::add_long_run_options(app, run);
  tool::add_output_option(app, output);
  tool::add_spreading_outputs(app, more, options.run);

  return tool::run(app, argc, argv,
                   [&] {
                     tool::Metadata meta("spreading", argc, argv);
                     const bool ensemble = options.run.realizations > 1 || run.resuming();
                     run.checkpoint = output + ".checkpoint";  // where an interrupted ensemble resumes from
                     validate(run);
                     KickedCase k = tool::kicked_case(options, ensemble);
                     const SelectedChain& selected = k.selected;
                     TransportCase& c = k.c;
                     c.profile_realizations = more.profile ? c.realizations : 0;
                     const SpreadingRunConfig& d = c.dynamics;
                     tool::ask_outputs(more, options.run, c);
                     if (!more.energy_map_file.empty() || d.covariant_vectors > 0)
                       load_hdf5_writer();  // before the run, not after it
                     const nlohmann::json step_rule = tool::validate_and_settle(c);
                     SpreadingPaths paths = spreading_paths(output, ensemble, more.profile, !d.forces.sites.empty(),
                                                            d.lyapunov_vectors > 0, d.covariant_vectors > 0);
                     paths.final_state = more.final_state, paths.energy_map = more.energy_map_file,
                     paths.spectrum = more.spectrum_file;
                     paths.deviation = options.deviation;
                     const auto claim = tool::claim_output(output, meta.command(),
                                                           ensemble ? std::optional<RunOptions>(run) : std::nullopt);
                     check_outputs(paths.all(), "--output/--final-state/--energy-map/--spectrum");
                     const bool single =
                         tool::single_outputs(more, c) || !options.deviation.empty();  // a run of its own

                     // Read before the run: resuming rewrites the checkpoint under this code's name.
                     const nlohmann::json resumed = ensemble ? resumed_code(run, {paths.checkpoint}) : nullptr;
                     std::optional<TransportSummary> summary;
                     if (ensemble) {
                       summary = tool::run_study(c.realizations, run, output, "spreading", argc, argv,
                                                 [&](const RunOptions& o) { return run_transport_study(c, o); });
                       if (!MpiContext::instance().root()) return;
                     }
                     const KickedChain kicked = kick(c, selected.chain);
                     const SpreadingResult r = !ensemble || single
                                                   ? run_spreading(selected.chain, kicked.initial, spreading_config(c))
                                                   : SpreadingResult{};
                     std::optional<TransportExponents> exponents = summary ? summary->exponents : std::nullopt;
                     if (!summary && c.fit) exponents = transport_exponents(c, r.t, r.m2, r.m2_centroid, r.ipr);
                     const TransportSummary* means = summary ? &*summary : nullptr;
                     for (const auto& note : run.quiet ? std::vector<std::string>{} : spreading_notes(c, r, means))
                       std::fprintf(stderr, "spreading: %s\n", note.c_str());
                     auto files = write_spreading_files(paths, r, means, d);
                     meta.merge(describe_spreading({.c = c,
                                                    .chain = selected.description,
                                                    .kicked = kicked,
                                                    .step_rule = step_rule,
                                                    .exponents = exponents,
                                                    .run = !summary || single ? &r : nullptr,
                                                    .realization = options.chain.realization,
                                                    .ensemble = means,
                                                    .threads = static_cast<int>(run.threads),
                                                    .resumed = resumed,
                                                    .paths = &paths}));
                     if (summary) tool::report_excluded(c, *summary, meta, run, "spreading", output, argv[0]);
                     meta["output"] = paths.csv;
                     meta.write(paths.json);  // the JSON first, then the rest: never an output without its metadata
                     files.commit();
                     if (ensemble) CheckpointLog::remove_all(paths.checkpoint);
                   },
                   {{"lyapunov", "--mle"}, {"amplitude", "--alpha"}, {"spectral_density", "--spectrum"}});
}
