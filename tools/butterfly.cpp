// butterfly: the Hofstadter butterfly of a quasiperiodic chain — every mode's frequency and IPR
// against the incommensurate ratio β — and the box-counting dimension of each β's spectrum; or, with
// --from dynamics, the same butterfly recovered as the power spectrum of a run.
// All the work is in study/butterfly.hpp and study/dynamical_butterfly.hpp; this file reads options
// and writes files.
#include <nlohmann/json.hpp>
#include <string>

#include "common/chain_options.hpp"
#include "common/dynamical_butterfly_options.hpp"
#include "common/outputs.hpp"
#include "common/tool_main.hpp"
#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/study/butterfly.hpp"
#include "granular/study/dynamical_butterfly.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "Every mode's frequency [kHz] and displacement IPR of a quasiperiodic chain for each ratio beta of a grid\n"
      "(the Hofstadter butterfly), and the box-counting dimension of each beta's spectrum.\n"
      "Writes PREFIX.csv (columns ratio,mode,freq_khz,ipr) and PREFIX.json (every parameter; box_counting:\n"
      "dimension and error per ratio, with the box sizes fitted).\n"
      "--from dynamics: for each beta the chain is run from small random velocities of every bead and the\n"
      "velocities' power summed over beads is written (columns ratio,freq_khz,power, max 1 per ratio); its\n"
      "peaks sit on the eigenfrequencies.",
      "butterfly"};
  tool::describe_common(app);
  tool::ChainOptions o;
  o.quasi = "s1";
  std::string output = "butterfly";
  ButterflyConfig config;
  RunOptions run;  // of how a long run goes, --threads alone
  bool quiet = false;
  tool::DynamicalButterflyOptions d;
  tool::add_quasiperiodic_options(app, o);
  app.remove_option(app.get_option("--ratio"));  // the ratios come from --ratios
  tool::add_parameters(app, config, butterfly_parameters(), {.only = {"ratios"}});
  tool::add_parameters(app, o, chain_parameters(), {.only = {"N", "F0", "R1", "seed", "realization"}});
  tool::add_parameters(app, config, butterfly_parameters(), {.except = {"ratios"}});
  tool::add_parameters(app, run, long_run_parameters(), {.only = {"threads"}});
  tool::add_dynamical_butterfly_options(app, d);
  tool::add_output_option(app, output);
  app.add_flag("--quiet", quiet, "no progress line on stderr");

  return tool::run(app, argc, argv, [&] {
    tool::Metadata meta("butterfly", argc, argv);
    validate(run);
    const bool dynamics = tool::from_dynamics(app, d, {"--largest-box", "--smallest-box", "--box-sizes"});
    config.chain = tool::chain_recipe(o);
    config.realization = chain_realization(o);
    DynamicalButterflyConfig& from_run = d.config;
    from_run.chain = config.chain, from_run.ratios = config.ratios, from_run.realization = config.realization;
    dynamics ? validate(from_run) : validate(config);
    const auto claim = tool::claim_output(output, meta.command());
    const TableOutputs paths = table_outputs(output);
    ProgressMeter progress(config.ratios.size(), dynamics ? "butterfly from dynamics" : "butterfly", quiet ? 0 : -1);
    run.progress = &progress;
    const auto write = [&](const auto& columns, const auto& write_csv, const nlohmann::json& described) {
      progress.finish();
      AtomicFile csv(paths.csv);
      write_csv(csv.stream(), columns);
      meta.merge(described);
      meta["threads"] = resolve_threads(run.threads);
      meta["output"] = paths.csv;
      meta.write(paths.json, {&csv});
    };
    if (dynamics) {
      const auto columns = compute_dynamical_butterfly(from_run, run);
      write(columns, write_dynamical_butterfly_csv, describe_dynamical_butterfly(from_run, columns));
    } else {
      const auto columns = compute_butterfly(config, run);
      write(columns, write_butterfly_csv, describe_butterfly(config, columns));
    }
  });
}
