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
  std::string output = "ipr-map";
  IprMapConfig config;
  // The chains: the two-type draw's --disorder, --N, --F0, --R1, --seed, --walls, or instead --quasi
  // or --types/--type-masses/--polydisperse (with --disorder as their rule), at the map's defaults.
  tool::ChainOptions beads = ipr_map_chain_defaults();
  RunOptions run;  // of how a long run goes, --threads alone
  ModeSelectionChoices selection;
  bool quiet = false;
  tool::add_parameters(app, beads, chain_parameters(), {.only = {"disorder"}});
  tool::add_parameters(app, config, ipr_map_parameters(), {.only = {"xi", "q"}});
  tool::add_parameters(app, beads, chain_parameters(), {.only = {"N", "F0", "R1", "walls"}});
  tool::add_parameters(app, config, ipr_map_parameters(), {.only = {"realizations"}});
  tool::add_parameters(app, beads, chain_parameters(), {.only = {"seed"}});
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
    validate(run);
    config.selection = choose_modes(selection);
    set_solver(config);
    set_chain(config, beads);  // --quasi or a bead distribution: one cell
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
