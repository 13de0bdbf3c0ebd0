#pragma once
// How an ensemble of kicked chains runs, shared by `spreading --realizations` and `exponents`:
// threads, checkpoint and resume (--resume continues, --fresh discards), what a failing
// realization does (stop with the command that replays it alone, or --skip-failed: leave it out,
// say so everywhere; a failed realization's case is written to a file that `spreading --case`
// replays, so every field travels), and Ctrl-C as a clean stop that prints the command resuming the run.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "granular/case/case_file.hpp"
#include "granular/ensemble/interrupt.hpp"
#include "granular/ensemble/resumed_checkpoint.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/io/shell_quote.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/study/transport_study.hpp"
#include "outputs.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// The library's run options (ensemble/run_options.hpp), bound straight to the flags, and --quiet.
struct LongRunOptions : RunOptions {
  bool quiet = false;
};

inline void add_long_run_options(CLI::App& app, LongRunOptions& o) {
  auto options = add_parameters<RunOptions>(app, o, long_run_parameters());
  options["resume"]->description(options["resume"]->get_description() + " PREFIX.checkpoint*");
  app.add_flag("--quiet", o.quiet, "no warnings, progress or final line on stderr");
}

/// The `spreading` command that computes realization `r` of case `c` alone, from its replay file
/// (case/case_file.hpp) beside the outputs on `prefix`; `argv0` (how this tool was called) says
/// where `spreading` is. When the file cannot be written, a sentence saying why.
inline std::string replay_text(const TransportCase& c, std::uint64_t r, const std::string& prefix,
                               const std::string& argv0) {
  std::string file;
  try {
    file = write_replay_case(c, r, prefix);
  } catch (const std::exception& e) {
    return std::string("(the case could not be written: ") + e.what() + ")";
  }
  const std::string folder = argv0.substr(0, argv0.rfind('/') + 1);  // "" without a slash
  return shell_quote(folder + "spreading") + " --case " + shell_quote(file) + " --realization " + std::to_string(r) +
         " --output replay-" + std::to_string(r);
}

/// Runs `study` (a call of run_transport_study or run_exponent_table with the RunOptions it is
/// given) over `total` realizations: a progress line (under mpirun on rank 0 alone), Ctrl-C as a
/// clean stop, checkpoints PREFIX.checkpoint[.<case>]. A realization failing in it becomes a
/// message that says how to replay it alone (its case file beside the outputs on `prefix`) and how
/// to go on without it (the realizations finished before it are in the checkpoint).
template <class Study>
auto run_study(std::size_t total, const LongRunOptions& o, const std::string& prefix, const char* tool, int argc,
               char** argv, const Study& study) {
  ProgressMeter progress(total, tool, o.quiet || !MpiContext::instance().root() ? 0 : -1);
  RunOptions options = o;
  options.checkpoint = prefix + ".checkpoint";
  validate(options);
  options.progress = &progress;
  options.cancelled = stop_on_interrupt(tool);
  try {
    auto result = study(options);
    progress.finish();
    return result;
  } catch (const RealizationFailed& e) {
    std::string go_on = resume_command(argc, argv);
    if (go_on.find(" --skip-failed") == std::string::npos) go_on += " --skip-failed";
    throw NumericalError(std::string(e.what()) +
                         "\n  replay it alone: " + replay_text(e.failed_case, e.realization, prefix, argv[0]) +
                         "\n  the realizations finished are kept; to go on without this one: " + go_on);
  }
}

/// Says which realizations of `c` were left out (--skip-failed): a line on stderr for each, with
/// its replay command (unless quiet), and a note on the final line.
inline void report_excluded(const TransportCase& c, const TransportSummary& s, Metadata& meta, const LongRunOptions& o,
                            const char* tool, const std::string& prefix, const std::string& argv0) {
  for (std::uint64_t r : o.quiet ? std::vector<std::uint64_t>{} : s.excluded)
    std::fprintf(stderr, "%s: realization %llu failed and is left out (--skip-failed); replay: %s\n", tool,
                 static_cast<unsigned long long>(r), replay_text(c, r, prefix, argv0).c_str());
  if (!s.excluded.empty()) meta.note(excluded_note(c, s));
}

}  // namespace granular::tool
