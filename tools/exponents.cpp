// exponents: the paper's transport study in one command — γ (m̃2 ∝ t^γ) and η (P⁻¹ ∝ t^−η)
// for every chain kind × F0 × kick, each averaged over an ensemble; Markdown tables on stdout,
// and with --compare-paper our γ beside the paper's Table I.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "common/dynamics_options.hpp"
#include "common/exponent_options.hpp"
#include "common/long_run_options.hpp"
#include "common/outputs.hpp"
#include "common/tool_main.hpp"
#include "granular/case/chain_length_rule.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/files/exponent_files.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/study/frequency_slips.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "The paper's transport exponents: for each kick, F0 and chain kind, R realizations of a kicked chain\n"
      "integrated to T; gamma and eta fitted on the averaged m2(t) and P^-1(t) (or, where that is not a power\n"
      "law, their mean log derivative), with sub-window spreads and realization (bootstrap) errors. Markdown\n"
      "tables on stdout; PREFIX.csv (exponents), PREFIX-curves.csv (mean curves), PREFIX-profiles.csv (E_n(T)),\n"
      "PREFIX.json; with --compare-paper, PREFIX-paper.csv and the side-by-side table. Interrupted runs\n"
      "continue with --resume (finished realizations are kept in PREFIX.checkpoint.*). Beyond the paper: one more "
      "chain\n"
      "from --types/--type-masses/--polydisperse named --chain-name, --ic mode (--mode/--near), --mle (X1 at T).",
      "exponents"};
  tool::describe_common(app);
  ExponentTableConfig config;  // the dynamics flags set its base case
  ExponentChoices choices;
  std::string output = "exponents";
  std::string paper_table = std::string(GRANULAR_SOURCE_DIR) + "/data/paper_table1_gamma.csv";
  tool::LongRunOptions run_options;
  bool compare = false;
  tool::add_parameters(app, config, exponent_table_parameters(), {.only = {"F0"}});
  tool::add_exponent_choices(app, choices, config);
  tool::add_parameters(app, choices.beads, long_run_chain_parameters(), {.only = {"N", "xi", "q", "walls"}});
  tool::add_dynamics_options(app, config.base);
  tool::add_parameters(app, config, exponent_table_parameters(), {.only = {"realizations"}});
  tool::add_parameters(app, choices.beads, chain_parameters(), {.only = {"seed"}});
  tool::add_parameters(app, config, exponent_table_parameters(), {.only = {"profile_F0", "profile_realizations"}});
  app.add_flag("--compare-paper", compare,
               "also print (and write PREFIX-paper.csv) our gamma beside the paper's Table I");
  tool::add_option(app, "--paper-table", paper_table, "the paper's Table I (CSV ic,F0_N,disorder,gamma,err,star)");
  tool::add_output_option(app, output, ", PREFIX-curves.csv, PREFIX-profiles.csv");
  tool::add_long_run_options(app, run_options);

  const auto body = [&] {
    tool::Metadata meta("exponents", argc, argv);
    const MpiContext& mpi = MpiContext::instance();
    set_chains(choices, config);
    run_options.checkpoint = output + ".checkpoint";  // where an interrupted table resumes from
    validate(run_options);
    TransportCase& base = config.base;
    const bool auto_n = config.automatic_length = choices.beads.auto_n;
    std::vector<TransportCase> cases = exponent_cases(config);
    const nlohmann::json rules = length_rules(cases, auto_n, static_cast<long long>(base.site));
    const nlohmann::json step_rule = tool::validate_and_settle(cases);
    tool::warn(frequency_slips(cases, [](const std::string& p) { return tool::option_name(front_end_word(p)); }));
    base.dynamics = cases.front().dynamics;  // τ and scheme as settled
    const auto paper = compare ? read_paper_table(paper_table) : std::vector<PaperCell>{};
    const ExponentPaths paths = exponent_paths(output, compare);
    const auto claim = tool::claim_output(output, meta.command(), run_options);
    for (const auto& p : paths.all()) check_writable(p);
    // Read before the run, which rewrites them.
    const nlohmann::json resumed = resumed_code(run_options, case_checkpoints(output + ".checkpoint", cases.size()));
    const auto cells = tool::run_study(total_realizations(cases), run_options, output, "exponents", argc, argv,
                                       [&](const RunOptions& o) { return run_exponent_table(config, cases, o); });
    if (!mpi.root()) return;

    std::printf("%s", markdown_tables(cells, config).c_str());
    const auto rows = compare ? compare_with_paper(cells, paper) : std::vector<CellComparison>{};
    if (compare) std::printf("%s", markdown_comparison(rows).c_str());
    const auto files = write_exponent_files(paths, cells, rows);
    for (const auto& c : cells)
      tool::report_excluded(c.definition, c.summary, meta, run_options, "exponents", output, argv[0]);
    meta.merge(describe_exponent_study(config, static_cast<int>(run_options.threads), cells, step_rule, resumed));
    if (auto_n) meta["chain_length_rule"] = rules;
    if (compare) meta["paper_table"] = paper_table;
    meta["output"] = paths.csv;
    meta.write(paths.json, files);  // the JSON first, then the CSVs: never a CSV without its metadata
    for (const auto& log : case_checkpoints(output + ".checkpoint", cells.size())) CheckpointLog::remove_all(log);
  };
  return tool::run(app, argc, argv, body, {{"disorder", "--chains"}, {"lyapunov", "--mle"}});
}
