#pragma once
// The kicked-chain case as `spreading` reads it: from its flags — the chain (chain_options.hpp,
// --N auto: case/chain_length_rule.hpp), the kick (--ic, the mode options), the dynamics and the tangent map — or
// whole from a case file (--case: a case description, as a replay file or a run's JSON holds it).
#include <set>
#include <string>

#include <CLI/CLI.hpp>

#include "chain_options.hpp"
#include "dynamics_options.hpp"
#include "granular/case/chain_length_rule.hpp"
#include "granular/case/kicked_case.hpp"
#include "granular/study/frequency_slips.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// The chain in words and the typed case, bound straight to the flags, with what only the command
/// line has: the file of the deviation vector (--deviation FILE turns on its samples) and the case
/// file. One realization unless --realizations says more.
struct KickedCaseOptions {
  KickedCaseOptions() { run.dynamics.deviation_samples = 20, run.realizations = 1; }
  ChainChoices chain = kicked_chain_defaults();
  TransportCase run;
  std::string deviation;  ///< CSV of the deviation vector's distribution; empty = none
  std::string case_file;  ///< --case: the chain, kick and dynamics from a file instead of the flags
};

inline void add_kicked_case_options(CLI::App& app, KickedCaseOptions& o) {
  const std::size_t before = app.get_options().size();
  add_chain_options(app, o.chain, long_run_chain_parameters());
  add_parameters(app, o.run, kicked_case_parameters(), {.only = {"ic"}});
  add_dynamics_options(app, o.run);
  add_parameters(app, o.run.mode, mode_kick_parameters());
  add_mle_options(app, o.run, "column mle = X1(t) [1/s] (ensemble: its mean)");
  app.add_option("--deviation", o.deviation, "CSV t,site,share: the deviation vector along the chain (with --mle)");
  add_parameters(app, o.run, transport_parameters(), {.only = {"deviation_samples"}})["deviation_samples"]->description(
      "uniform times of --deviation");
  auto spectrum = add_parameters(app, o.run, transport_parameters(), {.only = {"lyapunov_vectors"}});
  spectrum["lyapunov_vectors"]->description(spectrum["lyapunov_vectors"]->get_description() +
                                            ": PREFIX-lyapunov.csv (t, lambda_1.., gali_2.., sali)");
  auto clv = add_parameters(app, o.run, transport_parameters(), {.only = {"covariant_vectors", "covariant_transient"}});
  clv["covariant_vectors"]->description(clv["covariant_vectors"]->get_description() +
                                        ": PREFIX-clv.h5 (t, vectors, growth_rates, exponents, split_angles, "
                                        "participation, centre)");
  add_parameters(app, o.run, kicked_case_parameters(), {.only = {"realizations"}});
  auto* file = app.add_option("--case", o.case_file,
                              "JSON of a case: a replay file a failed ensemble wrote, or a spreading run's PREFIX.json "
                              "(its parameters); sets the chain, the kick and the dynamics, so none of their flags "
                              "goes with it; --realization and --realizations still choose what runs");
  const std::set<std::string> still{"--realization", "--realizations", "--deviation", "--deviation-samples"};
  const auto options = app.get_options();
  for (std::size_t i = before; i + 1 < options.size(); ++i)
    if (!still.contains(options[i]->get_name())) options[i]->excludes(file);
}

/// The case the options give, before validation (outputs may still add observers to it): the
/// library's kicked_case (case/kicked_case.hpp), its warnings printed. `ensemble` when it
/// averages realizations.
inline KickedCase kicked_case(const KickedCaseOptions& o, bool ensemble) {
  TransportCase run = o.run;
  if (o.deviation.empty() && o.run.dynamics.deviation_samples != KickedCaseOptions{}.run.dynamics.deviation_samples)
    throw InvalidInput("--deviation-samples", ": takes effect only with --deviation FILE (and --mle)");
  if (o.deviation.empty()) run.dynamics.deviation_samples = 0;
  KickedCase k = o.case_file.empty()
                     ? granular::kicked_case(o.chain, run, ensemble, radius_options(o.chain))
                     : granular::kicked_case(o.case_file, o.chain.realization, static_cast<long long>(run.realizations),
                                             static_cast<long long>(run.dynamics.deviation_samples), ensemble);
  warn(k.warnings);
  warn(frequency_slips(k.c.mode, k.c.chain, [](const std::string& p) { return option_name(front_end_word(p)); }));
  return k;
}

}  // namespace granular::tool
