// ipr-map: mean frequency and inverse participation ratio of every mode of disordered
// chains, over a grid of size ratios ξ and probabilities q (the paper's IPR-map figure).
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "common/chain_options.hpp"
#include "common/outputs.hpp"
#include "common/spectrum_options.hpp"
#include "common/tool_main.hpp"
#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/files/ipr_map_files.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/study/frequency_slips.hpp"
#include "granular/study/ipr_map_estimate.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "Mean mode frequency [kHz] and displacement IPR of disordered bidisperse chains on a (q, xi) grid.\n"
      "Writes PREFIX.csv (columns disorder,q,xi,mode,freq_khz,ipr) and PREFIX.json (every parameter).",
      "ipr-map"};
  tool::describe_common(app);
  std::string disorder = "A", output = "ipr-map";
  IprMapConfig config;
  tool::ChainOptions beads;  // --walls, --types/--type-masses/--polydisperse (with --disorder as their rule)
  RunOptions run;            // of how a long run goes, --threads alone
  ModeSelectionChoices selection;
  bool quiet = false;
  tool::add_option(app, "--disorder", disorder, "h | A | RDM1 | RDM2 (homogeneous, Anderson, random dimer 1/2)");
  tool::add_parameters(app, config, ipr_map_parameters(), {.only = {"xi", "q"}});
  tool::add_integer(app, "--N", config.chain.N, "beads per chain (>= 2)");
  tool::add_option(app, "--F0", config.chain.F0, "static precompression [N], > 0");
  tool::add_option(app, "--R1", config.chain.R1,
                   "radius of type-1 beads [m]; type 2 has xi*R1 (steel beads, steel walls)");
  tool::add_parameters(app, beads, chain_parameters(), {.only = {"walls"}});
  tool::add_parameters(app, config, ipr_map_parameters(), {.only = {"realizations"}});
  tool::add_integer(app, "--seed", config.chain.seed, "random seed; realization r of seed s is always the same chain");
  tool::add_parameters(app, run, long_run_parameters(), {.only = {"threads"}});
  tool::add_parameters(app, config, ipr_map_parameters(), {.only = {"solver"}});
  tool::add_output_option(app, output);
  tool::add_selection_options(app, selection, "partial spectra: ");
  tool::add_parameters(app, config, ipr_map_parameters(), {.only = {"method"}});
  tool::add_parameters(app, config, ipr_map_parameters(), {.only = {"bin_khz"}});
  tool::add_quasiperiodic_options(app, beads);  // one cell: realizations are phases
  tool::add_bead_distribution_options(app, beads);
  app.add_flag("--quiet", quiet, "no progress line on stderr");

  return tool::run(app, argc, argv, [&] {
    tool::Metadata meta("ipr-map", argc, argv);
    config.chain.draw().disorder = parse_disorder(disorder);
    if (config.chain.N > 100000000)
      throw InvalidInput("N", " " + std::to_string(config.chain.N) + ": more than 1e8 beads");
    validate(run);
    config.selection = choose_modes(selection);
    set_solver(config);
    beads.disorder = disorder;
    set_chain_kind(config, beads);  // --quasi or a bead distribution: one cell
    validate(config);
    tool::warn(radius_warnings(config.chain, tool::radius_options(beads)));
    tool::warn(frequency_slips(config, [](const std::string& p) { return tool::option_name(p); }));  // Hz as kHz
    const auto claim = tool::claim_output(output, meta.command());
    const TableOutputs paths = table_outputs(output);

    if (!quiet)  // a long map says so before it starts (its progress line counts chains)
      if (const IprMapEstimate e = estimate_ipr_map(config, resolve_threads(run.threads));
          e.seconds > announced_solve_seconds)
        std::fprintf(stderr, "ipr-map: %s\n", describe(e).c_str());
    ProgressMeter progress(config.q_values.size() * config.xi_values.size() * config.realizations, "ipr-map",
                           quiet ? 0 : -1);
    run.progress = &progress;
    const auto cells = compute_ipr_map(config, run);
    progress.finish();

    AtomicFile csv(paths.csv);
    write_ipr_map_csv(csv.stream(), config, cells);
    meta.merge(describe_ipr_map(config, cells, resolve_threads(run.threads)));
    meta["output"] = paths.csv;
    meta.write(paths.json, {&csv});
  });
}
