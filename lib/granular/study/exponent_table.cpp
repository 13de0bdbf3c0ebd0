#include "granular/study/exponent_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "granular/case/chain_length_rule.hpp"
#include "granular/case/transport_parameters.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/io/csv_writer.hpp"

namespace granular {

std::vector<std::string> chain_names(const ExponentTableConfig& config) {
  std::vector<std::string> names;
  for (Disorder d : config.chains) names.push_back(to_string(d));
  for (const BeadChain& b : config.bead_chains) names.push_back(b.name);
  return names;
}

std::string chain_name(const ExponentCell& cell) {
  return cell.chain.empty() ? to_string(cell.definition.chain.draw().disorder) : cell.chain;
}

void validate(const ExponentTableConfig& config) {
  if (config.chains.empty() && config.bead_chains.empty()) throw InvalidInput("chains", ": none given");
  if (config.kicks.empty()) throw InvalidInput("ic", ": none given");
  refuse_mode_without_mode_kick(config.base.mode, config.kicks);
  if (config.base.realizations < 1) throw InvalidInput("realizations", " 0: must be >= 1");
  for (std::size_t i = 0; i < config.bead_chains.size(); ++i) {
    const std::string& name = config.bead_chains[i].name;
    if (name.empty() || name.find_first_of(",\"\n\r") != std::string::npos)
      throw InvalidInput("chain_name", " '" + name + "': must be non-empty, without commas, quotes or line breaks");
    bool kind = true;  // a name that reads as a chain kind (h, A, anderson, rdm1, ...) would be ambiguous
    try {
      parse_disorder(name);
    } catch (const InvalidInput&) {
      kind = false;
    }
    if (kind) throw InvalidInput("chain_name", " '" + name + "': the name of a chain kind; choose another");
    for (std::size_t j = 0; j < i; ++j)
      if (config.bead_chains[j].name == name) throw InvalidInput("chain_name", " '" + name + "': given twice");
    if (!config.bead_chains[i].quasi) validate(config.bead_chains[i].beads);
  }
}

std::vector<TransportCase> exponent_cases(const ExponentTableConfig& config) {
  validate(config);
  std::vector<TransportCase> cases;
  const auto add = [&](TransportCase c) {
    const bool profile = std::find(config.profile_precompressions.begin(), config.profile_precompressions.end(),
                                   c.chain.F0) != config.profile_precompressions.end();
    c.profile_realizations = profile ? std::min(config.profile_realizations, c.realizations) : 0;
    if (config.automatic_length) size_for_long_times(c);  // (refuses a bead chain: no centred draw)
    cases.push_back(c);
  };
  for (Kick kick : config.kicks)
    for (double f0 : config.precompressions) {
      TransportCase c = config.base;
      c.kick = kick;
      c.chain.F0 = f0;
      const TwoTypeDraw* base = config.base.chain.as<TwoTypeDraw>();
      for (Disorder chain : config.chains) {
        TwoTypeDraw draw = base ? *base : TwoTypeDraw{};
        draw.disorder = chain;
        c.chain.source = draw;
        c.realizations = chain == Disorder::homogeneous ? 1 : config.base.realizations;  // one chain only
        add(c);
      }
      c.realizations = config.base.realizations;
      for (const BeadChain& b : config.bead_chains) {
        if (b.quasi) c.chain.source = *b.quasi;
        else c.chain.source = b.beads;
        add(c);
      }
    }
  return cases;
}

std::size_t total_realizations(const std::vector<TransportCase>& cases) {
  std::size_t total = 0;
  for (const auto& c : cases) total += c.realizations;
  return total;
}

std::vector<ExponentCell> run_exponent_table(const ExponentTableConfig& config, const std::vector<TransportCase>& cases,
                                             const RunOptions& options) {
  for (const auto& c : cases) validate(c);  // every case checked before the first one runs
  const std::vector<std::string> names = chain_names(config);
  std::vector<ExponentCell> cells;
  const std::vector<std::string> logs = case_checkpoints(options.checkpoint, cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    RunOptions run = options;
    run.checkpoint = options.checkpoint.empty() ? "" : logs[i];
    // A case not started before the interruption has no log yet: it simply starts.
    run.resume = options.resuming() && !run.checkpoint.empty() && CheckpointLog::exists(run.checkpoint);
    cells.push_back({cases[i], run_transport_study(cases[i], run), names[i % names.size()]});
  }
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

namespace {

bool any_mle(const std::vector<ExponentCell>& cells) {
  return std::any_of(cells.begin(), cells.end(), [](const ExponentCell& c) { return !c.summary.mle.mean.empty(); });
}

}  // namespace

MleAtEnd mle_at_end(const TransportSummary& s) {
  if (s.mle.mean.empty()) throw InvalidInput("lyapunov", ": the run had no tangent map (no X1 to report)");
  const double se = s.mle.standard_error.back();
  return {s.mle.mean.back(), se, se * std::sqrt(static_cast<double>(s.realizations))};
}

nlohmann::json to_json(const MleAtEnd& m) {
  return {{"X1_at_T_per_s", m.mean}, {"standard_error_per_s", m.standard_error}, {"spread_per_s", m.spread}};
}

std::vector<std::string> case_checkpoints(const std::string& prefix, std::size_t cases) {
  std::vector<std::string> logs;
  for (std::size_t i = 0; i < cases; ++i) logs.push_back(prefix + "." + std::to_string(i));
  return logs;
}

namespace {

/// One markdown table per call: a title, then a row per F0 and a column per chain, each cell
/// the text `cell` gives for that case ("—" where the study has no such case).
template <class CellText>
void append_table(std::string& out, const std::string& title, Kick kick, const std::vector<ExponentCell>& cells,
                  const ExponentTableConfig& config, CellText cell) {
  const std::vector<std::string> names = chain_names(config);
  out += "\n" + title + "\n\n| F0 [N] |";
  for (const std::string& name : names) out.append(" ").append(name).append(" |");
  out += "\n|---|";
  for (std::size_t i = 0; i < names.size(); ++i) out += "---|";
  out += "\n";
  for (double f0 : config.precompressions) {
    out.append("| ").append(format_number(f0)).append(" |");
    for (const std::string& name : names)
      for (const auto& c : cells)
        if (c.definition.kick == kick && c.definition.chain.F0 == f0 && chain_name(c) == name)
          out.append(" ").append(cell(c)).append(" |");
    out += "\n";
  }
}

}  // namespace

std::string markdown_tables(const std::vector<ExponentCell>& cells, const ExponentTableConfig& config) {
  std::string out;
  const std::string centre = to_string(config.base.centre);
  for (Kick kick : config.kicks)
    for (bool gamma : {true, false}) {
      const std::string title =
          (gamma ? "γ (m̃2 ∝ t^γ, m̃2 about the " + centre + ")" : std::string("η (P⁻¹ ∝ t^−η)")) + ", " +
          to_string(kick) +
          " kick (value ± spread over the fit sub-windows (± realization bootstrap); * = not a power law: "
          "|L_d − fit| ≥ κ after t*, the value is the mean L_d over the fit window)";
      append_table(out, title, kick, cells, config, [gamma](const ExponentCell& c) -> std::string {
        const auto& e = c.summary.exponents;
        return e ? cell_text(gamma ? e->gamma(c.definition.centre) : e->eta) : "—";
      });
    }
  if (!any_mle(cells)) return out;
  for (Kick kick : config.kicks) {
    const std::string title = "X1(T) [1/s], " + to_string(kick) +
                              " kick (maximal Lyapunov exponent at T by the tangent map: ensemble "
                              "mean ± its standard error; spread over realizations in PREFIX.csv)";
    append_table(out, title, kick, cells, config, [](const ExponentCell& c) -> std::string {
      if (c.summary.mle.mean.empty()) return "—";
      const MleAtEnd m = mle_at_end(c.summary);
      char text[64];
      std::snprintf(text, sizeof text, "%.4g ± %.2g", m.mean, m.standard_error);
      return text;
    });
  }
  return out;
}

void write_exponents_csv(std::ostream& out, const std::vector<ExponentCell>& cells) {
  std::vector<std::string> columns{"ic",
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
                                   "reached_walls"};
  const bool mle = any_mle(cells);  // only with the tangent map: other runs keep their columns
  if (mle) columns.insert(columns.end(), {"mle", "mle_real_err", "mle_sd"});
  CsvWriter table(out, columns);
  const auto flag = [](bool b) { return b ? "true" : "false"; };
  for (const auto& c : cells) {
    const auto& d = c.definition;
    const auto& s = c.summary;
    if (!s.exponents) continue;
    const SpreadCentre other = d.centre == SpreadCentre::site ? SpreadCentre::centroid : SpreadCentre::site;
    const ExponentReport &g = s.exponents->gamma(d.centre), &o = s.exponents->gamma(other), &e = s.exponents->eta;
    const auto row = [&](auto... more) {
      table.row(to_string(d.kick), d.chain.F0, chain_name(c), to_string(d.centre), g.shown().value, g.shown().error,
                g.shown_realization_error(), flag(g.starred()), g.fit.value, g.fit.error, g.fit_realization_error,
                g.mean_ld.value, g.mean_ld.error, g.mean_ld_realization_error, g.verdict.worst_deviation,
                to_string(other), o.shown().value, o.shown().error, o.shown_realization_error(), flag(o.starred()),
                o.fit.value, o.mean_ld.value, e.shown().value, e.shown().error, e.shown_realization_error(),
                flag(e.starred()), e.fit.value, e.fit.error, e.fit_realization_error, e.mean_ld.value, e.mean_ld.error,
                e.mean_ld_realization_error, e.verdict.worst_deviation, s.realizations, s.max_energy_error,
                s.reached_walls, more...);
    };
    if (!mle) row();
    else if (s.mle.mean.empty()) row("", "", "");
    else {
      const MleAtEnd m = mle_at_end(s);
      row(m.mean, m.standard_error, m.spread);
    }
  }
}

void write_curves_csv(std::ostream& out, const std::vector<ExponentCell>& cells) {
  std::vector<std::string> columns{"ic",  "F0",     "disorder",    "t", "m2", "m2_se", "m2_centroid", "m2_centroid_se",
                                   "ipr", "ipr_se", "energy_error"};
  const bool mle = any_mle(cells);
  if (mle) columns.insert(columns.end(), {"mle", "mle_se"});
  CsvWriter curve(out, columns);
  for (const auto& c : cells) {
    const auto& d = c.definition;
    const auto& s = c.summary;
    for (std::size_t i = 0; i < s.t.size(); ++i) {
      const auto row = [&](auto... more) {
        curve.row(to_string(d.kick), d.chain.F0, chain_name(c), s.t[i], s.m2.mean[i], s.m2.standard_error[i],
                  s.m2_centroid.mean[i], s.m2_centroid.standard_error[i], s.ipr.mean[i], s.ipr.standard_error[i],
                  s.energy_error.mean[i], more...);
      };
      if (!mle) row();
      else if (s.mle.mean.empty()) row("", "");
      else row(s.mle.mean[i], s.mle.standard_error[i]);
    }
  }
}

void write_profiles_csv(std::ostream& out, const std::vector<ExponentCell>& cells) {
  CsvWriter profile(out, {"ic", "F0", "disorder", "site", "energy", "energy_se"});
  for (const auto& c : cells) {
    const auto& d = c.definition;
    const auto& p = c.summary.profile;
    for (std::size_t i = 0; i < p.mean.size(); ++i)
      profile.row(to_string(d.kick), d.chain.F0, chain_name(c), i + 1, p.mean[i], p.standard_error[i]);
  }
}

}  // namespace granular
