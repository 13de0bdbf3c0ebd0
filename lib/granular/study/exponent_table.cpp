#include "granular/study/exponent_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/io/csv_writer.hpp"
#include "granular/study/chain_length_rule.hpp"

namespace granular {

std::vector<TransportCase> exponent_cases(const ExponentTableConfig& config) {
  std::vector<TransportCase> cases;
  for (Kick kick : config.kicks)
    for (double f0 : config.precompressions)
      for (Disorder chain : config.chains) {
        TransportCase c = config.base;
        c.kick = kick;
        c.precompression = f0;
        c.disorder = chain;
        if (chain == Disorder::homogeneous) c.realizations = 1;  // every realization is the same chain
        const bool profile = std::find(config.profile_precompressions.begin(), config.profile_precompressions.end(),
                                       f0) != config.profile_precompressions.end();
        c.profile_realizations = profile ? std::min(config.profile_realizations, c.realizations) : 0;
        if (config.automatic_length) {
          c.n = automatic_chain_length(c).n;
          c.site = (c.n - 1) / 2;
          c.centred_draw = true;
        }
        cases.push_back(c);
      }
  return cases;
}

std::vector<ExponentCell> run_exponent_table(const ExponentTableConfig& config, const ExponentRunOptions& options) {
  const auto cases = exponent_cases(config);
  for (const auto& c : cases) validate(c);  // every case checked before the first one runs
  std::size_t total = 0;
  for (const auto& c : cases) total += c.realizations;
  ProgressMeter own(total, "exponents", options.meter ? 0 : options.progress);
  std::vector<ExponentCell> cells;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    StudyRunOptions run;
    run.threads = options.threads;
    run.progress = options.meter ? options.meter : &own;
    run.cancelled = options.cancelled;
    run.skip_failed = options.skip_failed;
    if (!options.checkpoint_prefix.empty()) {
      run.checkpoint = options.checkpoint_prefix + "." + std::to_string(i);
      // A case not started before the interruption has no log yet: it simply starts.
      run.resume = options.resume && CheckpointLog::exists(run.checkpoint);
    }
    cells.push_back({cases[i], run_transport_study(cases[i], run)});
  }
  own.finish();
  return cells;
}

std::string cell_text(const ExponentReport& r) {
  char text[96];
  const ExponentEstimate& e = r.shown();
  const double real = r.shown_realization_error();
  if (std::isnan(real)) std::snprintf(text, sizeof text, "%.3f ± %.3f%s", e.value, e.error, r.starred() ? " *" : "");
  else
    std::snprintf(text, sizeof text, "%.3f ± %.3f (± %.3f real.)%s", e.value, e.error, real, r.starred() ? " *" : "");
  return text;
}

std::string markdown_tables(const std::vector<ExponentCell>& cells, const ExponentTableConfig& config) {
  std::string out;
  const std::string centre = to_string(config.base.centre);
  for (Kick kick : config.kicks)
    for (bool gamma : {true, false}) {
      out += "\n";
      out += gamma ? "γ (m̃2 ∝ t^γ, m̃2 about the " + centre + ")" : std::string("η (P⁻¹ ∝ t^−η)");
      out += ", " + to_string(kick);
      out +=
          " kick (value ± spread over the fit sub-windows (± realization bootstrap); * = not a power law: "
          "|L_d − fit| ≥ κ after t*, the value is the mean L_d over the fit window)\n\n| F0 [N] |";
      for (Disorder d : config.chains) out.append(" ").append(to_string(d)).append(" |");
      out += "\n|---|";
      for (std::size_t i = 0; i < config.chains.size(); ++i) out += "---|";
      out += "\n";
      for (double f0 : config.precompressions) {
        out.append("| ").append(format_number(f0)).append(" |");
        for (Disorder d : config.chains)
          for (const auto& c : cells)
            if (c.definition.kick == kick && c.definition.precompression == f0 && c.definition.disorder == d) {
              const auto& e = c.summary.exponents;
              out.append(" ").append(e ? cell_text(gamma ? e->gamma(c.definition.centre) : e->eta) : "—").append(" |");
            }
        out += "\n";
      }
    }
  return out;
}

void write_exponents_csv(std::ostream& out, const std::vector<ExponentCell>& cells) {
  CsvWriter table(out, {"ic",
                        "F0",
                        "disorder",
                        "centre",
                        "gamma",
                        "gamma_err",
                        "gamma_real_err",
                        "gamma_star",
                        "gamma_fit",
                        "gamma_fit_err",
                        "gamma_fit_real_err",
                        "gamma_mean_ld",
                        "gamma_mean_ld_err",
                        "gamma_mean_ld_real_err",
                        "worst_deviation_m2",
                        "other_centre",
                        "gamma_other",
                        "gamma_other_err",
                        "gamma_other_real_err",
                        "gamma_other_star",
                        "gamma_other_fit",
                        "gamma_other_mean_ld",
                        "eta",
                        "eta_err",
                        "eta_real_err",
                        "eta_star",
                        "eta_fit",
                        "eta_fit_err",
                        "eta_fit_real_err",
                        "eta_mean_ld",
                        "eta_mean_ld_err",
                        "eta_mean_ld_real_err",
                        "worst_deviation_ipr",
                        "realizations",
                        "max_energy_error",
                        "reached_walls"});
  const auto flag = [](bool b) { return b ? "true" : "false"; };
  for (const auto& c : cells) {
    const auto& d = c.definition;
    const auto& s = c.summary;
    if (!s.exponents) continue;
    const SpreadCentre other = d.centre == SpreadCentre::site ? SpreadCentre::centroid : SpreadCentre::site;
    const ExponentReport &g = s.exponents->gamma(d.centre), &o = s.exponents->gamma(other), &e = s.exponents->eta;
    table.row(to_string(d.kick), d.precompression, to_string(d.disorder), to_string(d.centre), g.shown().value,
              g.shown().error, g.shown_realization_error(), flag(g.starred()), g.fit.value, g.fit.error,
              g.fit_realization_error, g.mean_ld.value, g.mean_ld.error, g.mean_ld_realization_error,
              g.verdict.worst_deviation, to_string(other), o.shown().value, o.shown().error,
              o.shown_realization_error(), flag(o.starred()), o.fit.value, o.mean_ld.value, e.shown().value,
              e.shown().error, e.shown_realization_error(), flag(e.starred()), e.fit.value, e.fit.error,
              e.fit_realization_error, e.mean_ld.value, e.mean_ld.error, e.mean_ld_realization_error,
              e.verdict.worst_deviation, s.realizations, s.max_energy_error, s.reached_walls);
  }
}

void write_curves_csv(std::ostream& out, const std::vector<ExponentCell>& cells) {
  CsvWriter curve(out, {"ic", "F0", "disorder", "t", "m2", "m2_se", "m2_centroid", "m2_centroid_se", "ipr", "ipr_se",
                        "energy_error"});
  for (const auto& c : cells) {
    const auto& d = c.definition;
    const auto& s = c.summary;
    for (std::size_t i = 0; i < s.t.size(); ++i)
      curve.row(to_string(d.kick), d.precompression, to_string(d.disorder), s.t[i], s.m2.mean[i],
                s.m2.standard_error[i], s.m2_centroid.mean[i], s.m2_centroid.standard_error[i], s.ipr.mean[i],
                s.ipr.standard_error[i], s.energy_error.mean[i]);
  }
}

void write_profiles_csv(std::ostream& out, const std::vector<ExponentCell>& cells) {
  CsvWriter profile(out, {"ic", "F0", "disorder", "site", "energy", "energy_se"});
  for (const auto& c : cells) {
    const auto& d = c.definition;
    const auto& p = c.summary.profile;
    for (std::size_t i = 0; i < p.mean.size(); ++i)
      profile.row(to_string(d.kick), d.precompression, to_string(d.disorder), i + 1, p.mean[i], p.standard_error[i]);
  }
}

}  // namespace granular
