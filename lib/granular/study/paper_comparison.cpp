#include "granular/study/paper_comparison.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "granular/error.hpp"
#include "granular/io/csv_writer.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

double to_number(const std::string& text, const std::string& where) {
  if (text.empty()) return 0;
  if (const auto v = parse_finite_number(text)) return *v;
  throw InvalidInput(where + ": '" + text + "' is not a number");
}

double z_score(double delta, double variance) {
  if (variance > 0) return delta / std::sqrt(variance);
  return delta == 0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), delta);
}

CentreComparison compare(const PaperCell& p, const ExponentReport& r, std::size_t realizations) {
  CentreComparison c;
  c.value = r.shown().value;
  c.window_error = r.shown().error;
  c.realization_error = std::isnan(r.shown_realization_error()) ? 0 : r.shown_realization_error();
  c.starred = r.starred();
  const double delta = c.value - p.gamma;
  const double window = c.window_error * c.window_error + p.error * p.error + paper_rounding * paper_rounding;
  const double paper_real = c.realization_error * std::sqrt(static_cast<double>(realizations) / paper_realizations);
  c.z_window = z_score(delta, window);
  c.z = z_score(delta, window + c.realization_error * c.realization_error + paper_real * paper_real);
  return c;
}

std::string z_text(double z) {
  if (std::isinf(z)) return z > 0 ? "+∞" : "−∞";
  char t[32];
  std::snprintf(t, sizeof t, "%+.1f", z);
  return t;
}

std::string value_text(const CentreComparison& c) {
  char t[96];
  std::snprintf(t, sizeof t, "%.3f ± %.3f (± %.3f)%s", c.value, c.window_error, c.realization_error,
                c.starred ? " *" : "");
  return t;
}

}  // namespace

std::vector<PaperCell> read_paper_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot read the paper's table " + path);
  std::vector<PaperCell> cells;
  std::string line;
  bool header = false;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      if (line != "ic,F0_N,disorder,gamma,err,star")
        throw InvalidInput(path + ": expected the header ic,F0_N,disorder,gamma,err,star");
      header = true;
      continue;
    }
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string item; std::getline(fields, item, ',');) f.push_back(item);
    if (f.size() == 5) f.emplace_back();  // a trailing empty field
    const std::string where = path + " line " + std::to_string(number);
    if (f.size() != 6) throw InvalidInput(where + ": expected 6 fields");
    PaperCell c;
    c.kick = parse_kick(f[0]);
    c.precompression = to_number(f[1], where);
    c.disorder = parse_disorder(f[2]);
    c.gamma = to_number(f[3], where);
    c.error = to_number(f[4], where);
    c.starred = f[5] == "1";
    cells.push_back(c);
  }
  if (cells.empty()) throw InvalidInput(path + ": no rows");
  return cells;
}

std::vector<CellComparison> compare_with_paper(const std::vector<ExponentCell>& cells,
                                               const std::vector<PaperCell>& paper) {
  std::vector<CellComparison> rows;
  for (const PaperCell& p : paper)
    for (const ExponentCell& c : cells) {
      const TransportCase& d = c.definition;
      const TwoTypeDraw* draw = d.chain.as<TwoTypeDraw>();  // other sources: chains of the user's own
      if (!draw || d.kick != p.kick || d.chain.F0 != p.precompression || draw->disorder != p.disorder) continue;
      if (!c.summary.exponents) continue;
      CellComparison row;
      row.paper = p;
      row.realizations = c.summary.realizations;
      row.site = compare(p, c.summary.exponents->gamma_site, row.realizations);
      row.centroid = compare(p, c.summary.exponents->gamma_centroid, row.realizations);
      rows.push_back(row);
    }
  return rows;
}

std::string markdown_comparison(const std::vector<CellComparison>& rows) {
  std::string out =
      "\nγ beside the paper's Table I (value ± sub-window spread (± realization bootstrap); * = starred: mean L_d; "
      "z_w uses the sub-window spreads only, z adds both ensembles' realization errors)\n\n"
      "| kick | F0 [N] | chain | paper | ours, m̃2 about the site | z_w | z | ours, m̃2 about the centroid | z_w | z |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  std::size_t within[2][2] = {{0, 0}, {0, 0}};  // [site, centroid][2σ, 3σ] on z
  for (const auto& r : rows) {
    char paper[48];
    if (r.paper.error > 0)
      std::snprintf(paper, sizeof paper, "%.3f ± %.3f%s", r.paper.gamma, r.paper.error, r.paper.starred ? " *" : "");
    else std::snprintf(paper, sizeof paper, "%.3f%s", r.paper.gamma, r.paper.starred ? " *" : "");
    out += "| " + to_string(r.paper.kick) + " | " + format_number(r.paper.precompression) + " | " +
           to_string(r.paper.disorder) + " | " + paper + " | " + value_text(r.site) + " | " + z_text(r.site.z_window) +
           " | " + z_text(r.site.z) + " | " + value_text(r.centroid) + " | " + z_text(r.centroid.z_window) + " | " +
           z_text(r.centroid.z) + " |\n";
    for (int k = 0; k < 2; ++k) {
      const double z = std::fabs(k == 0 ? r.site.z : r.centroid.z);
      within[k][0] += z <= 2;
      within[k][1] += z <= 3;
    }
  }
  char summary[256];
  std::snprintf(summary, sizeof summary,
                "\n|z| ≤ 2 in %zu of %zu cells about the site, %zu about the centroid; |z| ≤ 3 in %zu and %zu.\n",
                within[0][0], rows.size(), within[1][0], within[0][1], within[1][1]);
  return out + summary;
}

void write_comparison_csv(std::ostream& out, const std::vector<CellComparison>& rows) {
  CsvWriter csv(out, {"ic", "F0", "disorder", "paper_gamma", "paper_err", "paper_star", "realizations", "site_gamma",
                      "site_err", "site_real_err", "site_star", "site_z_window", "site_z", "centroid_gamma",
                      "centroid_err", "centroid_real_err", "centroid_star", "centroid_z_window", "centroid_z"});
  const auto flag = [](bool b) { return b ? "true" : "false"; };
  for (const auto& r : rows)
    csv.row(to_string(r.paper.kick), r.paper.precompression, to_string(r.paper.disorder), r.paper.gamma, r.paper.error,
            flag(r.paper.starred), r.realizations, r.site.value, r.site.window_error, r.site.realization_error,
            flag(r.site.starred), r.site.z_window, r.site.z, r.centroid.value, r.centroid.window_error,
            r.centroid.realization_error, flag(r.centroid.starred), r.centroid.z_window, r.centroid.z);
}

}  // namespace granular
