// The statistics of a spectrum: the level-spacing ratio ⟨r⟩ against its known values for
// uncorrelated (Poisson) levels and the Gaussian orthogonal ensemble, the vector IPR's limits and
// the frequency histogram (docs/crystals.md, "Spectra").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "granular/crystal/crystal_spectrum.hpp"
#include "granular/linear/detail/lapack.hpp"
#include "granular/model/random_stream.hpp"

namespace granular {
namespace {

// Poisson: P(r) = 2/(1+r)², ⟨r⟩ = 2 ln 2 − 1 = 0.38629, σ_r² = 3 − 4 ln 2 − ⟨r⟩² (σ_r = 0.2796).
TEST(SpacingRatio, UncorrelatedLevelsGivePoisson) {
  RandomStream stream(17, 0);
  std::vector<double> levels(200000);
  for (double& e : levels) e = stream.uniform();
  std::sort(levels.begin(), levels.end());
  const SpacingRatio r = spacing_ratio(levels);
  const double mean = 2 * std::numbers::ln2 - 1;
  const double sigma = std::sqrt(3 - 4 * std::numbers::ln2 - mean * mean);
  // Neighbouring ratios share a spacing: allow twice the independent standard error, times 4.
  const double error = 2 * sigma / std::sqrt(static_cast<double>(r.count));
  EXPECT_EQ(r.count, levels.size() - 2);
  EXPECT_NEAR(r.mean, mean, 4 * error) << "standard error " << error;
}

// GOE: symmetric matrices with N(0, 1) off the diagonal, N(0, 2) on it; ⟨r⟩ = 0.5307 (Atas et al.
// 2013, large N) from the middle half of each spectrum, where the density is nearly flat.
TEST(SpacingRatio, GaussianOrthogonalEnsembleGivesGoe) {
  const int n = 200, matrices = 60;
  RandomStream stream(23, 0);
  auto gauss = [&] {  // Box–Muller
    const double u = 1 - stream.uniform(), v = stream.uniform();
    return std::sqrt(-2 * std::log(u)) * std::cos(2 * std::numbers::pi * v);
  };
  double sum = 0, sum2 = 0;
  std::size_t count = 0;
  std::vector<double> a(static_cast<std::size_t>(n * n)), w(static_cast<std::size_t>(n));
  for (int m = 0; m < matrices; ++m) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j <= i; ++j) {
        const double x = i == j ? std::sqrt(2.0) * gauss() : gauss();
        a[static_cast<std::size_t>(i * n + j)] = a[static_cast<std::size_t>(j * n + i)] = x;
      }
    const char jobz = 'N', uplo = 'L';
    int lwork = 4 * n + 1, liwork = 1, info = 0;
    std::vector<double> work(static_cast<std::size_t>(lwork));
    std::vector<int> iwork(1);
    dsyevd_(&jobz, &uplo, &n, a.data(), &n, w.data(), work.data(), &lwork, iwork.data(), &liwork, &info, 1, 1);
    ASSERT_EQ(info, 0);
    const SpacingRatio r = spacing_ratio(std::span<const double>(w.data() + n / 4, static_cast<std::size_t>(n / 2)));
    sum += r.mean * static_cast<double>(r.count), count += r.count;
    for (int k = n / 4; k + 2 < 3 * n / 4; ++k) {
      const double s0 = w[static_cast<std::size_t>(k + 1)] - w[static_cast<std::size_t>(k)];
      const double s1 = w[static_cast<std::size_t>(k + 2)] - w[static_cast<std::size_t>(k + 1)];
      const double x = std::min(s0, s1) / std::max(s0, s1);
      sum2 += x * x;
    }
  }
  const double mean = sum / static_cast<double>(count);
  const double sigma = std::sqrt(sum2 / static_cast<double>(count) - mean * mean);
  const double error = 2 * sigma / std::sqrt(static_cast<double>(count));
  EXPECT_NEAR(mean, 0.5307, 4 * error) << "standard error " << error << " from " << count << " ratios";
  EXPECT_GT(mean, 0.3863 + 20 * error);  // and far from Poisson
}

TEST(SpacingRatio, SkipsExactDegeneraciesAndWindows) {
  const std::vector<double> levels{0, 1, 1, 1, 3, 4};
  // Spacings 1 0 0 2 1: ratios 0, skip (0/0), 0, 0.5.
  const SpacingRatio r = spacing_ratio(levels);
  EXPECT_EQ(r.count, 3u);
  EXPECT_DOUBLE_EQ(r.mean, 0.5 / 3);
  CrystalSpectrum s;
  s.freq_hz = levels;
  EXPECT_EQ(spacing_ratio(s, 2.5, 10).count, 0u);
  EXPECT_THROW(spacing_ratio(s, 3, 3), InvalidInput);
}

TEST(VectorIpr, OneBeadIsOneAndAPlaneWaveIsOneOverN) {
  const std::vector<double> inverse_sqrt_mass{0.5, 2.0, 1.0, 1.0};
  std::vector<double> w(8, 0.0);
  w[3] = 0.7;  // bead 1, y
  EXPECT_DOUBLE_EQ(vector_ipr(w, inverse_sqrt_mass), 1.0);
  // Equal displacements (v = M^{-1/2} w) in any polarization: 1/N.
  for (std::size_t b = 0; b < 4; ++b) w[2 * b] = 0.6 / inverse_sqrt_mass[b], w[2 * b + 1] = 0.8 / inverse_sqrt_mass[b];
  EXPECT_DOUBLE_EQ(vector_ipr(w, inverse_sqrt_mass), 0.25);
}

TEST(FrequencyHistogram, CountsEveryModeInsideOnceAndIntegratesToTheirFraction) {
  CrystalSpectrum s;
  s.freq_hz = {-5, 0, 1, 2.5, 2.5, 9.99, 10, 12};
  s.omega2.assign(s.freq_hz.size(), 0.0);
  const FrequencyHistogram h = frequency_histogram(s, 4, 0, 10);
  EXPECT_EQ(h.edges, (std::vector<double>{0, 2.5, 5, 7.5, 10}));
  EXPECT_EQ(h.counts, (std::vector<std::size_t>{2, 2, 0, 2}));  // 10 is in the last bin
  double integral = 0;
  for (std::size_t k = 0; k < 4; ++k) integral += h.density[k] * 2.5;
  EXPECT_DOUBLE_EQ(integral, 6.0 / 8);
  EXPECT_THROW(frequency_histogram(s, 0, 0, 10), InvalidInput);
  EXPECT_THROW(frequency_histogram(s, 4, 1, 1), InvalidInput);
}

}  // namespace
}  // namespace granular
