// correlations: ensemble mean and spread of the Pearson coefficient ρ(d) of bead types (k types
// or polydisperse radii: bead masses) with their cyclic shifts, beside the infinite-chain formula
// (docs/physics.md, "Disorder").
#include <nlohmann/json.hpp>
#include <string>

#include "common/chain_options.hpp"
#include "common/outputs.hpp"
#include "common/tool_main.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/files/correlation_files.hpp"
#include "granular/io/atomic_file.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "Pearson correlation rho(d) of bead types (type 1 -> 0, type 2 -> 1) with their cyclic shift by d,\n"
      "averaged over realizations: columns distance,rho_mean,rho_std,rho_theory (theory: infinite chain).\n"
      "With --types/--type-masses (k types, drawn by --disorder) or --polydisperse: rho(d) of the bead masses,\n"
      "for two types the same coefficient (Pearson is invariant under the affine map type -> mass).",
      "correlations"};
  tool::describe_common(app);
  std::string output = "correlations";
  CorrelationConfig config;
  RunOptions run;  // of how a long run goes, --threads alone
  bool quiet = false;
  // The chains: the two-type draw's --disorder (h has no correlation: one type only), --q, --N,
  // --seed, or --types/--type-masses/--polydisperse (drawn by --disorder), at the study's defaults.
  tool::ChainOptions beads = correlation_chain_defaults();
  tool::add_parameters(app, beads, chain_parameters(), {.only = {"disorder", "q"}});
  tool::add_bead_distribution_options(app, beads);
  tool::add_parameters(app, beads, chain_parameters(), {.only = {"N"}});
  tool::add_parameters(app, config, correlation_parameters(), {.only = {"realizations"}});
  tool::add_parameters(app, beads, chain_parameters(), {.only = {"seed"}});
  CLI::Option* max_distance =
      tool::add_parameters(app, config, correlation_parameters(), {.only = {"max_distance"}})["max_distance"];
  tool::add_parameters(app, run, long_run_parameters(), {.only = {"threads"}});
  tool::add_output_option(app, output);
  app.add_flag("--quiet", quiet, "no final report on stderr");

  return tool::run(app, argc, argv, [&] {
    tool::Metadata meta("correlations", argc, argv);
    set_chain(config, beads);
    // The default must fit short chains (N = 2 has only d = 0, 1); a value typed is checked as typed.
    if (max_distance->count() == 0 && config.chain.N >= 2 && config.max_distance > config.chain.N - 1)
      config.max_distance = config.chain.N - 1;
    validate(run);
    validate(config);
    const auto claim = tool::claim_output(output, meta.command());
    const TableOutputs paths = table_outputs(output);

    const CorrelationResult result = correlation_study(config, run);
    AtomicFile csv(paths.csv);
    write_correlations_csv(csv.stream(), result);
    meta.merge(describe_correlations(config, result));
    meta["output"] = paths.csv;
    meta.write(paths.json, {&csv});
  });
}
