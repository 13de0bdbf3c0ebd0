// crystal-ipr-map: the 2D analogue of the paper's IPR map (docs/crystals.md, "The IPR map"): the
// mean vector IPR and the level-spacing ratio <r> of disordered crystals' modes in frequency bins,
// per disorder width, over realizations on threads and MPI ranks, checkpointed and resumable.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "common/long_run_options.hpp"
#include "common/outputs.hpp"
#include "common/tool_main.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/files/crystal_files.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/output_paths.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/parameter_json.hpp"
#include "granular/study/crystal_ipr_map.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "IPR map of 2D granular crystals: every mode (dense LAPACK) of --realizations crystals per disorder width\n"
      "(--widths), binned in frequency (--bin-hz): the mean vector IPR and the level-spacing ratio <r> per bin\n"
      "(Poisson 0.3863: localized; GOE 0.5307: extended). Crystals of up to a few thousand beads, or larger ones\n"
      "with --near F --count K: the K modes nearest F kHz of each (sparse shift-invert, ARPACK); the crystals\n"
      "are shared by --threads and by the ranks of mpirun, and the map does not depend on either. Writes\n"
      "PREFIX.csv (width,freq_lo_khz,freq_hi_khz,modes,ipr,ratio,ratios) and PREFIX.json (every parameter);\n"
      "PREFIX.checkpoint logs each solved crystal until the map is written: --resume continues a killed run.",
      "crystal-ipr-map"};
  tool::describe_common(app);
  CrystalIprMapConfig c;
  std::string output = "crystal-ipr-map";
  tool::LongRunOptions run;
  tool::add_parameters(app, c, crystal_ipr_map_parameters());
  tool::add_parameters<RunOptions>(app, run, long_run_parameters(), {.except = {"skip_failed"}})["resume"]->description(
      "continue an interrupted run (same parameters) from PREFIX.checkpoint");
  app.add_flag("--quiet", run.quiet, "no progress or final line on stderr");
  tool::add_output_option(app, output);

  return tool::run(app, argc, argv, [&] {
    tool::Metadata meta("crystal-ipr-map", argc, argv);
    validate(c);
    run.checkpoint = output + ".checkpoint";
    validate(run);
    const TableOutputs paths = table_outputs(output);
    const auto claim = tool::claim_output(output, meta.command(), std::optional<RunOptions>(run));
    const bool writer = MpiContext::instance().root();
    const nlohmann::json resumed = resumed_code(run, {run.checkpoint});  // before the run rewrites it

    ProgressMeter progress(c.widths.size() * c.realizations, "crystal-ipr-map", run.quiet || !writer ? 0 : -1);
    RunOptions options = run;
    options.progress = &progress;
    options.cancelled = stop_on_interrupt("crystal-ipr-map");
    const auto cells = crystal_ipr_map(c, options);
    progress.finish();
    if (!writer) return;

    AtomicFile csv(paths.csv);
    write_crystal_ipr_map_csv(csv.stream(), c, cells);
    meta["parameters"] = describe_rows(c, crystal_ipr_map_parameters());
    meta["threads"] = resolve_threads(run.threads);
    meta["ranks"] = MpiContext::instance().size();
    if (!resumed.is_null()) meta["resumed_checkpoint"] = resumed;
    meta["output"] = paths.csv;
    meta.write(paths.json, {&csv});
    CheckpointLog::remove_all(run.checkpoint);
  });
}
