// localization: localization length and density of states of one long chain by transfer
// matrices — the Lyapunov exponent λ(f) with its statistical error, ℓ = 1/λ, and the integrated
// and differential density of states from node counts (docs/physics.md, "Infinite chains"). A random
// chain is streamed, so N = 1e8 needs no more memory than N = 100.
#include <nlohmann/json.hpp>
#include <string>

#include "common/chain_options.hpp"
#include "common/outputs.hpp"
#include "common/tool_main.hpp"
#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/files/localization_files.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/range_syntax.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "Transfer-matrix Lyapunov exponent and node-count density of states of one chain, at a list of\n"
      "frequencies. Writes PREFIX.csv (columns freq_khz,lyapunov,lyapunov_err,loc_length,idos,dos,resolved:\n"
      "kHz, 1/bead, 1/bead, beads, modes per bead, modes per bead per kHz, 1 where loc_length is a\n"
      "measurement: lambda >= 10 ln(N)/N and N/segments >= 10 loc_length, else 0) and PREFIX.json (every\n"
      "parameter, and that rule as resolved_rule).",
      "localization"};
  tool::describe_common(app);
  tool::ChainOptions chain_options = localization_chain();
  tool::add_chain_options(app, chain_options);
  std::string frequencies = localization_frequencies, output = "localization";
  LocalizationScanConfig config;  // its frequencies from --f
  RunOptions run;                 // of how a long run goes, --threads alone
  bool quiet = false;
  tool::add_option(app, "--f", frequencies,
                   "frequencies [kHz]: start:stop[:step] (step 0.01, stop included) or a,b,c; increasing");
  tool::add_integer(app, "--segments", config.segments,
                    "chain pieces whose exponents give lyapunov_err (2 ... 1e6, at most N)");
  tool::add_parameters(app, run, long_run_parameters(), {.only = {"threads"}});
  tool::add_output_option(app, output);
  app.add_flag("--quiet", quiet, "no progress line and no final report on stderr");

  return tool::run(app, argc, argv,
                   [&] {
                     tool::Metadata meta("localization", argc, argv);
                     config.frequency_khz = parse_number_list(frequencies, "--f", 0.01);
                     validate(config);
                     validate(run);
                     const StreamedChain chain = tool::stream_chain(chain_options, localization_chain());
                     for (double f : config.frequency_khz)  // the first one above the chain's frequencies
                       if (tool::warn({frequency_warning("--f", f, chain.highest_frequency_khz)})) break;
                     const auto claim = tool::claim_output(output, meta.command());
                     const TableOutputs paths = table_outputs(output);

                     ProgressMeter progress(chain.beads->size() * config.frequency_khz.size(), "localization",
                                            quiet ? 0 : -1);
                     run.progress = &progress;
                     const LocalizationScan scan = localization_scan(*chain.beads, config, run);
                     progress.finish();

                     AtomicFile csv(paths.csv);
                     write_localization_csv(csv.stream(), scan);
                     meta.merge(describe_localization(scan, chain.description, frequencies,
                                                      resolve_threads(run.threads), steel));
                     meta["output"] = paths.csv;
                     meta.write(paths.json, {&csv});
                   },
                   {{"frequencies", "--f"}});
}
