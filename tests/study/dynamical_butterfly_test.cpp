// The butterfly from the dynamics (study/dynamical_butterfly.hpp): its peaks against the
// eigenfrequencies of the linear solver (an independent method) within the resolution 1/T, at zero
// modulation and at a rational ratio; thread-count invariance; inputs refused by name.
#include <gtest/gtest.h>

#include <cmath>

#include "granular/error.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/study/dynamical_butterfly.hpp"

namespace granular {
namespace {

DynamicalButterflyConfig dynbfly_config(Quasiperiodic::Kind kind, double modulation, std::size_t n) {
  DynamicalButterflyConfig c;
  c.chain.N = n;
  c.chain.source = Quasiperiodic{.kind = kind, .modulation = modulation, .phase = 0.4};
  c.integration.duration = 2e-2;  // resolution 50 Hz, far below the level spacings of 12 beads
  c.spectrum_samples = 4001;      // Nyquist 100 kHz
  return c;
}

// Every eigenfrequency of the chain at `ratio` has a local maximum of the power within 1/T, and every
// local maximum above 1e-6 of the largest lies within 1/T of an eigenfrequency. With every bead of one
// mass the bead sum has no cross terms between modes: the power is a sum of one Dirichlet kernel per
// mode, each falling monotonically away from its frequency on the DFT's grid, so the only local maxima
// are the modes (and, far below 1e-6, the Hertz law's harmonics).
void dynbfly_expect_peaks_on_modes(const DynamicalButterflyConfig& c, const DynamicalButterflyColumn& col) {
  ChainRecipe recipe = c.chain;
  recipe.as<Quasiperiodic>()->ratio = col.ratio;
  const Spectrum s = spectrum(dynamical_matrix(recipe.chain(c.realization)));
  const double resolution_khz = 1 / c.integration.duration / 1e3;
  const std::vector<double>& f = col.freq_khz;
  const std::vector<double>& g = col.power;
  ASSERT_GT(f.size(), 3u);
  ASSERT_GT(f.back(), s.freq_khz.back() + 1);  // the whole spectrum is below Nyquist
  const auto is_peak = [&](std::size_t j) { return j > 0 && j + 1 < g.size() && g[j] > g[j - 1] && g[j] > g[j + 1]; };
  for (double mode : s.freq_khz) {
    bool found = false;
    for (std::size_t j = 0; j < f.size(); ++j) found = found || (std::abs(f[j] - mode) <= resolution_khz && is_peak(j));
    EXPECT_TRUE(found) << "no peak within 1/T of the eigenfrequency " << mode << " kHz at ratio " << col.ratio;
  }
  std::size_t peaks = 0;
  for (std::size_t j = 0; j < f.size(); ++j) {
    if (!is_peak(j) || g[j] < 1e-6) continue;
    ++peaks;
    double nearest = INFINITY;
    for (double mode : s.freq_khz) nearest = std::min(nearest, std::abs(f[j] - mode));
    EXPECT_LE(nearest, resolution_khz) << "a peak at " << f[j] << " kHz (power " << g[j] << ") is no mode";
  }
  EXPECT_EQ(peaks, s.freq_khz.size());
}

TEST(DynamicalButterfly, PeaksSitOnTheEigenfrequenciesAtZeroModulation) {
  DynamicalButterflyConfig c = dynbfly_config(Quasiperiodic::Kind::cylinders, 0, 12);
  c.ratios = {0.618};
  const auto columns = compute_dynamical_butterfly(c, {.threads = 1});
  ASSERT_EQ(columns.size(), 1u);
  dynbfly_expect_peaks_on_modes(c, columns[0]);
  EXPECT_LT(columns[0].initial_energy / columns[0].opening_energy, 1e-6);  // linear
  EXPECT_LT(columns[0].max_energy_error, 1e-6);
}

TEST(DynamicalButterfly, PeaksSitOnTheEigenfrequenciesAtARationalRatio) {
  DynamicalButterflyConfig c = dynbfly_config(Quasiperiodic::Kind::s1, 0.4, 12);
  // Bands of 3 or 4 modes: levels 0.1 kHz apart, so a resolution of 10 Hz (T = 0.1 s) separates them.
  c.integration.duration = 0.1;
  c.spectrum_samples = 20001;
  c.ratios = {1.0 / 3, 0.25};
  const auto columns = compute_dynamical_butterfly(c, {.threads = 2});
  ASSERT_EQ(columns.size(), 2u);
  for (const auto& col : columns) dynbfly_expect_peaks_on_modes(c, col);
}

TEST(DynamicalButterfly, DoesNotDependOnTheThreadCount) {
  DynamicalButterflyConfig c = dynbfly_config(Quasiperiodic::Kind::cylinders, 0.3, 10);
  c.integration.duration = 2e-3;
  c.spectrum_samples = 401;
  c.ratios = {0.2, 0.5, 0.618, 0.9};
  const auto one = compute_dynamical_butterfly(c, {.threads = 1});
  const auto two = compute_dynamical_butterfly(c, {.threads = 2});
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].ratio, c.ratios[i]);
    EXPECT_EQ(one[i].power, two[i].power);
    EXPECT_EQ(one[i].freq_khz, two[i].freq_khz);
  }
}

std::string dynbfly_refused(const DynamicalButterflyConfig& c) {
  try {
    validate(c);
  } catch (const InvalidInput& e) {
    return e.parameter();
  }
  return "(accepted)";
}

TEST(DynamicalButterfly, BadInputsAreRefusedByName) {
  DynamicalButterflyConfig good = dynbfly_config(Quasiperiodic::Kind::cylinders, 0.3, 10);
  good.ratios = {0.5};
  EXPECT_EQ(dynbfly_refused(good), "(accepted)");
  auto c = good;
  c.ratios = {0.5, 0};
  EXPECT_EQ(dynbfly_refused(c), "ratios");
  c = good, c.ratios.clear();
  EXPECT_EQ(dynbfly_refused(c), "ratios");
  c = good, c.chain.source = TwoTypeDraw{};
  EXPECT_EQ(dynbfly_refused(c), "quasi");
  c = good, c.amplitude = 0;
  EXPECT_EQ(dynbfly_refused(c), "amplitude");
  c = good, c.amplitude = 1;  // 1 m/s on every bead opens contacts: not the linear chain
  EXPECT_EQ(dynbfly_refused(c), "amplitude");
  c = good, c.integration.time_step = 1e-4;
  EXPECT_EQ(dynbfly_refused(c), "time_step");
  c = good, c.spectrum_samples = 101;  // Nyquist 2.5 kHz: the peaks would alias
  EXPECT_EQ(dynbfly_refused(c), "spectrum_samples");
  c = good, c.spectrum_samples = 3000;  // 2999 intervals do not divide 20000 steps: the samples stop short of T
  EXPECT_EQ(dynbfly_refused(c), "spectrum_samples");
  c = good, c.chain.F0 = 0;
  EXPECT_EQ(dynbfly_refused(c), "F0");
  c = good, c.integration.duration = -1;
  EXPECT_EQ(dynbfly_refused(c), "duration");
  c = good, c.chain.as<Quasiperiodic>()->modulation = 1.5;
  EXPECT_EQ(dynbfly_refused(c), "modulation");
}

}  // namespace
}  // namespace granular
