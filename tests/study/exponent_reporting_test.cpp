// What the exponent tables show (docs/physics.md, "Nonlinear dynamics"): a fitted slope for a power law, the mean L_d
// with a star otherwise; and the comparison with the paper's Table I.
#include <cmath>
#include <numbers>
#include <sstream>

#include <gtest/gtest.h>

#include "granular/analysis/exponent_report.hpp"
#include "granular/error.hpp"
#include "granular/study/exponent_table.hpp"
#include "granular/study/paper_comparison.hpp"

namespace granular {
namespace {

std::vector<double> fit_grid() {
  std::vector<double> t;
  for (int k = 0; k <= 600; ++k) t.push_back((4000 + 10 * k) * 1e-6);
  return t;
}

TEST(ExponentReporting, LogPeriodicSeriesShowsItsMeanLdWithAStar) {
  // y = t^1.5 (1 + a sin φ), φ = 2π ln t / ln 2: d ln y / d ln t = 1.5 + a (2π/ln 2) cos φ / (1 + a sin φ),
  // which swings by ±0.45 for a = 0.05 — markedly not a power law. The table must show the mean of
  // L_d over the window, computed here from that analytic derivative at the grid's midpoints.
  const double a = 0.05, k = 2 * std::numbers::pi / std::log(2.0);
  const std::vector<double> t = fit_grid();
  std::vector<double> y;
  for (double s : t) y.push_back(std::pow(s, 1.5) * (1 + a * std::sin(k * std::log(s))));
  double expected = 0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double phase = k * std::log(std::sqrt(t[i] * t[i + 1]));
    expected += 1.5 + a * k * std::cos(phase) / (1 + a * std::sin(phase));
  }
  expected /= static_cast<double>(t.size() - 1);
  const ExponentReport r = report_exponent(t, y, 4e-3, 1e-2, {0.1, 4e-3});
  EXPECT_TRUE(r.starred());
  EXPECT_NEAR(r.mean_ld.value, expected, 1e-4);
  EXPECT_EQ(&r.shown(), &r.mean_ld);
  EXPECT_GT(std::fabs(r.fit.value - r.mean_ld.value), 1e-3) << "the test needs fit and mean L_d to differ";
  char text[128];
  std::snprintf(text, sizeof text, "%.3f ± %.3f *", r.mean_ld.value, r.mean_ld.error);
  EXPECT_EQ(cell_text(r), text);
  // With a realization error it is printed beside the sub-window spread.
  ExponentReport with = r;
  with.mean_ld_realization_error = 0.0123;
  std::snprintf(text, sizeof text, "%.3f ± %.3f (± 0.012 real.) *", r.mean_ld.value, r.mean_ld.error);
  EXPECT_EQ(cell_text(with), text);
}

TEST(ExponentReporting, PowerLawShowsItsFitWithoutAStar) {
  const std::vector<double> t = fit_grid();
  std::vector<double> y;
  for (double s : t) y.push_back(2 * std::pow(s, 1.763));
  const ExponentReport r = report_exponent(t, y, 4e-3, 1e-2, {});
  EXPECT_FALSE(r.starred());
  EXPECT_EQ(&r.shown(), &r.fit);
  EXPECT_EQ(cell_text(r), "1.763 ± 0.000");
}

TEST(PaperComparison, ReadsTableIFromData) {
  const auto table = read_paper_table(std::string(GRANULAR_DATA_DIR) + "/paper_table1_gamma.csv");
  ASSERT_EQ(table.size(), 40u);
  int stars = 0;
  for (const auto& c : table) stars += c.starred;
  EXPECT_EQ(stars, 4);                 // displacement kick, A and RDM2, at 10 and 0.5 N
  const PaperCell& sonic = table[37];  // velocity, 0, A
  EXPECT_EQ(sonic.kick, Kick::velocity);
  EXPECT_EQ(sonic.precompression, 0.0);
  EXPECT_EQ(sonic.disorder, Disorder::anderson);
  EXPECT_DOUBLE_EQ(sonic.gamma, 1.763);
  EXPECT_DOUBLE_EQ(sonic.error, 0.012);
  EXPECT_EQ(table[0].error, 0.0);  // h: no ± printed
  EXPECT_THROW(read_paper_table("/nonexistent/table.csv"), IoError);
}

TEST(PaperComparison, ZScoresByHand) {
  // Ours 1.800 ± 0.010 (sub-windows) ± 0.020 (bootstrap, R = 125); paper 1.763 ± 0.012 (R = 500).
  // The paper's realization error is estimated as ours scaled to R = 500: 0.020 √(125/500) = 0.010.
  // The paper's rounding to 3 decimals adds p² = 0.0005²/3 = 8.33e-8.
  // Δ = 0.037; z_w = 0.037 / √(0.010² + 0.012² + p²) = 2.3684…;
  // z = 0.037 / √(0.010² + 0.012² + p² + 0.020² + 0.010²) = 0.037 / √0.00074408 = 1.3564….
  ExponentCell cell;
  cell.definition.kick = Kick::velocity;
  cell.definition.chain.F0 = 0;
  cell.definition.chain.draw().disorder = Disorder::anderson;
  TransportExponents e;
  e.gamma_site.fit = {1.8, 0.01, {}};
  e.gamma_site.verdict.power_law = true;
  e.gamma_site.fit_realization_error = 0.02;
  e.gamma_centroid = e.gamma_site;
  e.gamma_centroid.verdict.power_law = false;  // starred: its mean L_d is compared
  e.gamma_centroid.mean_ld = {1.763, 0.0, {}};
  e.gamma_centroid.mean_ld_realization_error = 0.0;
  cell.summary.exponents = e;
  cell.summary.realizations = 125;
  const PaperCell paper{Kick::velocity, 0, Disorder::anderson, 1.763, 0.012, false};
  const auto rows =
      compare_with_paper({cell}, {paper, PaperCell{Kick::velocity, 10, Disorder::anderson, 1.457, 0.011, false}});
  ASSERT_EQ(rows.size(), 1u);  // the 10 N cell is not in our run
  const double p2 = 0.0005 * 0.0005 / 3;
  EXPECT_NEAR(rows[0].site.z_window, 0.037 / std::sqrt(0.0001 + 0.000144 + p2), 1e-9);
  EXPECT_NEAR(rows[0].site.z, 0.037 / std::sqrt(0.000744 + p2), 1e-9);
  EXPECT_TRUE(rows[0].centroid.starred);
  EXPECT_NEAR(rows[0].centroid.z, 0.0, 1e-12);
  // A homogeneous cell: no ± anywhere, only the paper's rounding: 2.0003 vs 2.000 is z = 0.0003/p ≈ 1.04.
  ExponentCell h = cell;
  h.definition.chain.draw().disorder = Disorder::homogeneous;
  h.summary.exponents->gamma_site = ExponentReport{};
  h.summary.exponents->gamma_site.fit = {2.0003, 0.0, {}};
  h.summary.exponents->gamma_site.verdict.power_law = true;
  h.summary.realizations = 1;
  const auto homogeneous =
      compare_with_paper({h}, {PaperCell{Kick::velocity, 0, Disorder::homogeneous, 2.0, 0.0, false}});
  ASSERT_EQ(homogeneous.size(), 1u);
  EXPECT_NEAR(homogeneous[0].site.z, 0.0003 / std::sqrt(p2), 1e-6);
  std::ostringstream csv;
  write_comparison_csv(csv, rows);
  EXPECT_EQ(
      csv.str().substr(0, csv.str().find('\n')),
      "ic,F0,disorder,paper_gamma,paper_err,paper_star,realizations,site_gamma,site_err,site_real_err,site_star,"
      "site_z_window,site_z,centroid_gamma,centroid_err,centroid_real_err,centroid_star,centroid_z_window,centroid_z");
  EXPECT_NE(markdown_comparison(rows).find("|z| ≤ 2 in 1 of 1 cells about the site, 1 about the centroid"),
            std::string::npos);
}

}  // namespace
}  // namespace granular
