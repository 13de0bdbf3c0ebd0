// exponents: the paper's transport study in one command — γ (m̃2 ∝ t^γ) and η (P⁻¹ ∝ t^−η)
// for every chain kind × F0 × kick, each averaged over an ensemble; Markdown tables on stdout,
// and with --compare-paper our γ beside the paper's Table I.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "common/dynamics_options.hpp"
#include "common/exponent_options.hpp"
#include "common/long_run_options.hpp"
#include "common/long_time_options.hpp"
#include "common/metadata.hpp"
#include "common/tool_main.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/study/paper_comparison.hpp"

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
      "from --types/--type-masses/--polydisperse named --chain-name, --ic mode (--mode/--mode-khz), --mle (X1 at T).",
      "exponents"};
  tool::describe_common(app);
  tool::DynamicsOptions dynamics;
  tool::ExponentChoices choices;
  std::string f0_text = "10,0.5,0.1,0.01,0", output = "exponents", profile_f0 = "10,0.1,0";
  std::string paper_table = std::string(GRANULAR_SOURCE_DIR) + "/data/paper_table1_gamma.csv";
  long long n = 2501, realizations = 500, seed = 1, profile_realizations = 100;
  double xi = 0.5, q = 0.5;
  tool::LongRunOptions run_options;
  bool compare = false, auto_n = false;
  app.add_option("--F0", f0_text, "precompressions [N], comma list (0 = sonic vacuum)")->capture_default_str();
  tool::add_exponent_choices(app, choices, dynamics.beyond);
  app.add_option("--N", n, "beads per chain")->capture_default_str();
  app.add_option("--xi", xi, "size ratio R2/R1 in (0,1]")->capture_default_str();
  app.add_option("--q", q, "disorder probability in [0,1]")->capture_default_str();
  tool::add_dynamics_options(app, dynamics);
  app.add_option("--realizations", realizations, "realizations per disordered case (h always runs 1)")
      ->capture_default_str();
  app.add_option("--seed", seed, "random seed")->capture_default_str();
  app.add_option("--profile-F0", profile_f0, "F0s whose energy profile E_n(T) is averaged (list; 'none')")
      ->capture_default_str();
  app.add_option("--profile-realizations", profile_realizations, "realizations averaged in those profiles")
      ->capture_default_str();
  app.add_flag("--compare-paper", compare,
               "also print (and write PREFIX-paper.csv) our gamma beside the paper's Table I");
  app.add_option("--paper-table", paper_table, "the paper's Table I (CSV ic,F0_N,disorder,gamma,err,star)")
      ->capture_default_str();
  tool::add_output_option(app, output, ", PREFIX-curves.csv, PREFIX-profiles.csv");
  tool::add_long_run_options(app, run_options);
  tool::add_auto_length(app, auto_n);

  return tool::run(app, argc, argv,
                   [&] {
                     tool::Metadata meta("exponents", argc, argv);
                     const MpiContext& mpi = MpiContext::instance();
                     ExponentTableConfig config;
                     tool::apply(choices, config);
                     config.precompressions = parse_number_list(f0_text, "--F0");
                     config.profile_precompressions =
                         profile_f0 == "none" ? std::vector<double>{} : parse_number_list(profile_f0, "--profile-F0");
                     if (profile_realizations < 0) throw InvalidInput("--profile-realizations: must be >= 0");
                     config.profile_realizations = static_cast<std::size_t>(profile_realizations);
                     if (n < 2) throw InvalidInput("--N " + std::to_string(n) + ": a chain needs at least 2 beads");
                     if (n > 100000000) throw InvalidInput("--N " + std::to_string(n) + ": more than 1e8 beads");
                     if (realizations < 1)
                       throw InvalidInput("--realizations " + std::to_string(realizations) + ": must be >= 1");
                     if (seed < 0) throw InvalidInput("--seed: must be >= 0");
                     if (run_options.threads < 0) throw InvalidInput("--threads: must be >= 0");
                     TransportCase& base = config.base;
                     base.chain.N = static_cast<std::size_t>(n);
                     base.chain.xi = xi;
                     base.chain.q = q;
                     base.chain.seed = static_cast<std::uint64_t>(seed);
                     base.realizations = static_cast<std::size_t>(realizations);
                     std::vector<PaperCell> paper;
                     std::vector<std::string> paths{output + ".csv", output + "-curves.csv", output + "-profiles.csv",
                                                    output + ".json"};
                     tool::apply(dynamics, base);
                     config.automatic_length = auto_n;
                     std::vector<TransportCase> cases = exponent_cases(config);
                     const nlohmann::json length_rules = tool::length_rules(cases, auto_n, dynamics.choices.site);
                     for (const auto& c : cases) validate(c);
                     const nlohmann::json step_rule = tool::settle_time_step(cases, dynamics, app.count("--dt") > 0);
                     base.dynamics = cases.front().dynamics;  // τ and scheme as settled
                     if (compare) paper = read_paper_table(paper_table);
                     if (compare) paths.push_back(output + "-paper.csv");
                     const tool::OutputClaim claim(output, meta.command(), run_options.checkpoints());
                     for (const auto& p : paths) check_writable(p);
                     ExponentRunOptions run;
                     run.threads = run_options.threads;
                     run.checkpoint_prefix = output + ".checkpoint";
                     run.resume = run_options.resuming();
                     run.accept_other_version = run_options.other_version;
                     run.progress = run_options.quiet || !mpi.root() ? 0 : -1;
                     run.cancelled = tool::stop_on_interrupt("exponents");
                     std::vector<std::string> logs;  // read before the run, which rewrites them
                     for (std::size_t i = 0; i < cases.size(); ++i)
                       logs.push_back(run.checkpoint_prefix + "." + std::to_string(i));
                     const nlohmann::json resumed = tool::resumed_code(run_options, logs);
                     run.skip_failed = run_options.skip_failed;
                     const auto cells =
                         tool::replaying_failures([&] { return run_exponent_table(config, run); }, argc, argv);
                     if (!mpi.root()) return;

                     std::printf("%s", markdown_tables(cells, config).c_str());
                     AtomicFile csv(paths[0]), curves(paths[1]), profiles(paths[2]);
                     write_exponents_csv(csv.stream(), cells);
                     write_curves_csv(curves.stream(), cells);
                     write_profiles_csv(profiles.stream(), cells);
                     nlohmann::json cases_json = nlohmann::json::array();
                     for (const auto& c : cells) {
                       nlohmann::json one = describe(c.definition);
                       one["failed_excluded"] =
                           tool::report_excluded(c.definition, c.summary, meta, run_options, "exponents", argv[0]);
                       if (c.summary.exponents)
                         one["exponents"] = {{"gamma_site", to_json(c.summary.exponents->gamma_site)},
                                             {"gamma_centroid", to_json(c.summary.exponents->gamma_centroid)},
                                             {"eta", to_json(c.summary.exponents->eta)}};
                       if (!c.summary.mle.mean.empty()) one["mle"] = to_json(mle_at_end(c.summary));
                       one["chain"] = chain_name(c);
                       cases_json.push_back(one);
                     }
                     meta["parameters"] = {{"chains", choices.chains},
                                           {"F0", config.precompressions},
                                           {"ic", choices.kicks},
                                           {"threads", run_options.threads},
                                           {"mpi_ranks", mpi.size()}};
                     meta["cases"] = cases_json;
                     meta["time_step_rule"] = step_rule;
                     if (!resumed.is_null()) meta["resumed_checkpoint"] = resumed;
                     if (auto_n) meta["chain_length_rule"] = length_rules;
                     std::optional<AtomicFile> comparison;
                     if (compare) {
                       const auto rows = compare_with_paper(cells, paper);
                       std::printf("%s", markdown_comparison(rows).c_str());
                       comparison.emplace(paths[4]);
                       write_comparison_csv(comparison->stream(), rows);
                       meta["paper_table"] = paper_table;
                     }
                     meta["output"] = paths[0];
                     if (comparison)  // the JSON first, then the CSVs: never a CSV without its metadata
                       meta.write(paths[3], {&csv, &curves, &profiles, &*comparison});
                     else meta.write(paths[3], {&csv, &curves, &profiles});
                     for (std::size_t i = 0; i < cells.size(); ++i)
                       CheckpointLog::remove_all(run.checkpoint_prefix + "." + std::to_string(i));
                   },
                   {{"disorder", "--chains"}, {"lyapunov", "--mle"}, {"near_khz", "--mode-khz"}});
}
