// exponents: the paper's transport study in one command — γ (m̃2 ∝ t^γ) and η (P⁻¹ ∝ t^−η)
// for every chain kind × F0 × kick, each averaged over an ensemble; Markdown tables on stdout.
#include <cstdio>
#include <map>
#include <string>

#include "common/metadata.hpp"
#include "common/tool_main.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/csv_writer.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/study/exponent_table.hpp"

namespace {

using namespace granular;

std::string cell_text(const PowerLawAnalysis& a) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f ± %.3f%s", a.exponent.value, a.exponent.error, a.verdict.power_law ? "" : " †");
  return text;
}

void print_table(const std::vector<ExponentCell>& cells, Kick kick, bool gamma, const ExponentTableConfig& config) {
  std::printf("\n%s, %s kick (± = spread over the fit sub-windows; † = not a power law: |L_d − fit| ≥ κ after t*)\n\n",
              gamma ? "γ (m̃2 ∝ t^γ)" : "η (P⁻¹ ∝ t^−η)", to_string(kick).c_str());
  std::printf("| F0 [N] |");
  for (Disorder d : config.chains) std::printf(" %s |", to_string(d).c_str());
  std::printf("\n|---|");
  for (std::size_t i = 0; i < config.chains.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (double f0 : config.precompressions) {
    std::printf("| %s |", format_number(f0).c_str());
    for (Disorder d : config.chains)
      for (const auto& c : cells)
        if (c.definition.kick == kick && c.definition.precompression == f0 && c.definition.disorder == d)
          std::printf(" %s |", cell_text(gamma ? c.summary.gamma : c.summary.eta).c_str());
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The paper's transport exponents: for each kick, F0 and chain kind, R realizations of a kicked chain\n"
               "integrated to T; gamma and eta fitted on the averaged m2(t) and P^-1(t). Markdown tables on stdout;\n"
               "PREFIX.csv (exponents), PREFIX-curves.csv (mean curves), PREFIX-profiles.csv (E_n(T)), PREFIX.json.\n"
               "Interrupted runs continue with --resume (finished realizations are kept in PREFIX.checkpoint.*).",
               "exponents"};
  tool::describe_common(app);
  std::string chains = "h,A,RDM1,RDM2", f0_text = "10,0.5,0.1,0.01,0", kicks = "displacement,velocity";
  std::string output = "exponents", fit_text = "4e-3:1e-2", beta_text = "8e-3", integrator = "saba2c", sampling = "log";
  std::string profile_f0 = "10,0.1,0";
  long long n = 2501, realizations = 500, seed = 1, samples = 100, site = 0, profile_realizations = 100;
  double xi = 0.5, q = 0.5, duration = 1e-2, dt = 1e-6, alpha = 1e-7, kappa = 0.1;
  int threads = 0;
  bool resume = false, quiet = false, no_window = false;
  app.add_option("--chains", chains, "chain kinds: comma list of h, A, RDM1, RDM2")->capture_default_str();
  app.add_option("--F0", f0_text, "precompressions [N], comma list (0 = sonic vacuum)")->capture_default_str();
  app.add_option("--ic", kicks, "kicks: displacement, velocity or both")->capture_default_str();
  app.add_option("--N", n, "beads per chain")->capture_default_str();
  app.add_option("--site", site, "kicked bead, 1-based (0 = the centre, (N+1)/2)")->capture_default_str();
  app.add_option("--xi", xi, "size ratio R2/R1 in (0,1]")->capture_default_str();
  app.add_option("--q", q, "disorder probability in [0,1]")->capture_default_str();
  app.add_option("--T", duration, "integration time [s]")->capture_default_str();
  app.add_option("--dt", dt, "time step tau [s]")->capture_default_str();
  app.add_option("--alpha", alpha, "displacement kick [m]")->capture_default_str();
  app.add_option("--beta", beta_text, "velocity kick [m/s], or 'match' (the energy of --alpha on each chain)")->capture_default_str();
  app.add_option("--integrator", integrator, "saba2c | aba864 | srkn14a | reference")->capture_default_str();
  app.add_option("--realizations", realizations, "realizations per disordered case (h always runs 1)")->capture_default_str();
  app.add_option("--seed", seed, "random seed")->capture_default_str();
  app.add_option("--samples", samples, "sample times of m2 and P^-1, log-spaced from tau to T")->capture_default_str();
  app.add_option("--fit", fit_text, "fit interval start:stop [s]")->capture_default_str();
  app.add_option("--kappa", kappa, "'not a power law' when |L_d - fit| >= kappa after the fit start")->capture_default_str();
  app.add_option("--profile-F0", profile_f0, "F0s whose energy profile E_n(T) is averaged (list; 'none')")->capture_default_str();
  app.add_option("--profile-realizations", profile_realizations, "realizations averaged in those profiles")->capture_default_str();
  app.add_option("--threads", threads, "threads per process (0 = all cores); results do not depend on it")->capture_default_str();
  app.add_option("--output", output, "output prefix")->capture_default_str();
  app.add_flag("--resume", resume, "continue an interrupted run with the same parameters");
  app.add_flag("--no-window", no_window, "integrate the whole chain (no active window)");
  app.add_flag("--quiet", quiet, "no progress line");

  return tool::run(app, argc, argv, [&] {
    tool::Metadata meta("exponents", argc, argv);
    const MpiContext& mpi = MpiContext::instance();
    ExponentTableConfig config;
    config.chains.clear();
    for (const auto& name : parse_word_list(chains, "--chains")) config.chains.push_back(parse_disorder(name));
    config.precompressions = parse_number_list(f0_text, "--F0");
    config.kicks.clear();
    for (const auto& name : parse_word_list(kicks, "--ic")) config.kicks.push_back(parse_kick(name));
    config.profile_precompressions = profile_f0 == "none" ? std::vector<double>{} : parse_number_list(profile_f0, "--profile-F0");
    if (profile_realizations < 0) throw InvalidInput("--profile-realizations: must be >= 0");
    config.profile_realizations = static_cast<std::size_t>(profile_realizations);
    if (n < 2) throw InvalidInput("--N " + std::to_string(n) + ": a chain needs at least 2 beads");
    if (n > 100000000) throw InvalidInput("--N " + std::to_string(n) + ": more than 1e8 beads");
    if (realizations < 1) throw InvalidInput("--realizations " + std::to_string(realizations) + ": must be >= 1");
    if (seed < 0) throw InvalidInput("--seed: must be >= 0");
    if (samples < 2) throw InvalidInput("--samples " + std::to_string(samples) + ": need at least 2");
    if (site < 0 || site > n) throw InvalidInput("--site " + std::to_string(site) + ": outside the chain");
    if (threads < 0) throw InvalidInput("--threads: must be >= 0");
    const Interval fit_interval = parse_interval(fit_text, "--fit");
    const std::vector<double> fit{fit_interval.start, fit_interval.stop};

    TransportCase& base = config.base;
    base.n = static_cast<std::size_t>(n);
    base.site = site == 0 ? (base.n - 1) / 2 : static_cast<std::size_t>(site - 1);
    base.xi = xi;
    base.q = q;
    base.alpha = alpha;
    if (beta_text == "match") {
      base.match_beta = true;
    } else {
      const auto b = parse_number_list(beta_text, "--beta", 0, 1);
      if (b.size() != 1 || !(b[0] != 0)) throw InvalidInput("--beta '" + beta_text + "': a non-zero number or 'match'");
      base.beta = b[0];
    }
    base.dynamics.duration = duration;
    base.dynamics.time_step = dt;
    base.dynamics.integrator = integrator;
    base.dynamics.samples = static_cast<std::size_t>(samples);
    base.dynamics.window.enabled = !no_window;
    base.seed = static_cast<std::uint64_t>(seed);
    base.realizations = static_cast<std::size_t>(realizations);
    base.fit_begin = fit[0];
    base.fit_end = fit[1];
    base.criterion.kappa = kappa;
    base.criterion.t_start = fit[0];

    const std::string csv_path = output + ".csv", curves_path = output + "-curves.csv",
                      profiles_path = output + "-profiles.csv", json_path = output + ".json";
    for (const auto* p : {&csv_path, &curves_path, &profiles_path, &json_path}) check_writable(*p);
    ExponentRunOptions run;
    run.threads = threads;
    run.checkpoint_prefix = output + ".checkpoint";
    run.resume = resume;
    run.progress = quiet || !mpi.root() ? 0 : -1;
    const auto cells = run_exponent_table(config, run);
    if (!mpi.root()) return;

    for (Kick kick : config.kicks) {
      print_table(cells, kick, true, config);
      print_table(cells, kick, false, config);
    }
    AtomicFile csv(csv_path), curves(curves_path), profiles(profiles_path);
    CsvWriter table(csv.stream(), {"ic", "F0", "disorder", "gamma", "gamma_err", "eta", "eta_err", "power_law_m2",
                                   "power_law_ipr", "worst_deviation_m2", "worst_deviation_ipr", "realizations",
                                   "max_energy_error", "reached_walls"});
    CsvWriter curve(curves.stream(), {"ic", "F0", "disorder", "t", "m2", "m2_se", "ipr", "ipr_se", "energy_error"});
    CsvWriter profile(profiles.stream(), {"ic", "F0", "disorder", "site", "energy", "energy_se"});
    nlohmann::json cases = nlohmann::json::array();
    for (const auto& c : cells) {
      const auto& d = c.definition;
      const auto& s = c.summary;
      const std::string ic = to_string(d.kick), kind = to_string(d.disorder);
      table.row(ic, d.precompression, kind, s.gamma.exponent.value, s.gamma.exponent.error, s.eta.exponent.value,
                s.eta.exponent.error, s.gamma.verdict.power_law ? "true" : "false",
                s.eta.verdict.power_law ? "true" : "false", s.gamma.verdict.worst_deviation,
                s.eta.verdict.worst_deviation, s.realizations, s.max_energy_error, s.reached_walls);
      for (std::size_t i = 0; i < s.t.size(); ++i)
        curve.row(ic, d.precompression, kind, s.t[i], s.m2.mean[i], s.m2.standard_error[i], s.ipr.mean[i],
                  s.ipr.standard_error[i], s.energy_error.mean[i]);
      for (std::size_t i = 0; i < s.profile.mean.size(); ++i)
        profile.row(ic, d.precompression, kind, i + 1, s.profile.mean[i], s.profile.standard_error[i]);
      cases.push_back(describe(d));
    }
    meta["parameters"] = {{"chains", chains}, {"F0", config.precompressions}, {"ic", kicks}, {"fit_s", fit},
                          {"kappa", kappa}, {"log_step", base.criterion.log_step}, {"threads", threads},
                          {"mpi_ranks", mpi.size()}};
    meta["cases"] = cases;
    csv.commit();
    curves.commit();
    profiles.commit();
    meta.write(json_path);
    for (std::size_t i = 0; i < cells.size(); ++i) CheckpointLog::remove_all(run.checkpoint_prefix + "." + std::to_string(i));
  });
}
