// Spectra of the quasiperiodic chains (model/quasiperiodic.hpp) against independent results: the
// homogeneous chain at zero modulation, the Bloch bands of the q-periodic chain at β = p/q (a small
// dense Hermitian matrix solved by Eigen), and the Aubry–André transition of S1 (its Lyapunov
// exponent ln(λ k0 / 2K) by a hand-written transfer recursion).
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/chain_recipe.hpp"

namespace granular {
namespace {

using Kind = Quasiperiodic::Kind;
constexpr double pi = std::numbers::pi;

ChainRecipe quasi(Kind kind, double lambda, double beta, std::size_t n, double phase = 0.4) {
  ChainRecipe r{.N = n, .F0 = 10};
  r.source = Quasiperiodic{.kind = kind, .modulation = lambda, .ratio = beta, .phase = phase};
  return r;
}

std::vector<double> omega2(const Chain& c) { return spectrum(dynamical_matrix(c)).omega2; }

TEST(QuasiperiodicSpectrum, ZeroModulationIsTheHomogeneousChain) {
  const std::size_t n = 200;
  ChainRecipe h{.source = TwoTypeDraw{.disorder = Disorder::homogeneous}, .N = n, .F0 = 10};
  const auto hom = omega2(h.chain(0));
  const auto s2 = omega2(quasi(Kind::s2, 0, golden_mean, n).chain(0));
  const Chain s1_chain = quasi(Kind::s1, 0, golden_mean, n).chain(0);
  const auto s1 = omega2(s1_chain);
  const double shift = s1_chain.onsite[0] * s1_chain.inverse_mass[0];  // uniform k0/m: every ω² moves by it
  for (std::size_t j = 0; j < n; ++j) {
    EXPECT_NEAR(s2[j], hom[j], 1e-12 * hom.back());
    EXPECT_NEAR(s1[j], hom[j] + shift, 1e-12 * s1.back());
  }
  // Cylinders: every bond (walls included) has the coefficient of α0, so ω_j² = (4K/m) sin²(jπ/2(N+1)).
  const Chain c = quasi(Kind::cylinders, 0, golden_mean, n).chain(0);
  const auto cyl = omega2(c);
  const double K = linear_stiffness(c.contact[0], c.precompression);
  for (std::size_t j = 0; j < n; ++j) {
    const double s = std::sin(static_cast<double>(j + 1) * pi / (2.0 * static_cast<double>(n + 1)));
    EXPECT_NEAR(cyl[j], 4 * K / c.mass[0] * s * s, 1e-12 * cyl.back());
  }
}

/// The Bloch bands of the q-periodic chain whose sites 1…q are beads 1…q of `c` (bond k joins
/// sites k and k+1; bond q closes the cell with the Bloch phase θ): [lowest, highest] ω² of each
/// band over θ in [0, π].
std::vector<std::pair<double, double>> bloch_bands(const Chain& c, std::size_t q) {
  const auto b = linear_stiffness(c);
  std::vector<std::pair<double, double>> bands(q, {INFINITY, -INFINITY});
  for (int t = 0; t <= 400; ++t) {
    const double theta = pi * t / 400;
    Eigen::MatrixXcd d = Eigen::MatrixXcd::Zero(static_cast<long>(q), static_cast<long>(q));
    for (std::size_t n = 1; n <= q; ++n) {  // bead n is c's index n (walls are bond 0 and N)
      const long i = static_cast<long>(n - 1), j = static_cast<long>(n % q);
      const double onsite = c.onsite.empty() ? 0 : c.onsite[n];
      d(i, i) += (b[n] + b[n + 1] + onsite) / c.mass[n];  // bead n+1 of the chain (index n) has bonds n, n+1
      const std::complex<double> hop = -b[n + 1] / std::sqrt(c.mass[n] * c.mass[(n % q) + 1]);
      const std::complex<double> phase = n == q ? std::polar(1.0, theta) : 1.0;
      if (q == 1) {
        d(i, i) += 2 * (hop * phase).real();
      } else {
        d(i, j) += hop * phase;
        d(j, i) += std::conj(hop * phase);
      }
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> solver(d, Eigen::EigenvaluesOnly);
    for (std::size_t k = 0; k < q; ++k) {
      bands[k].first = std::min(bands[k].first, solver.eigenvalues()[static_cast<long>(k)]);
      bands[k].second = std::max(bands[k].second, solver.eigenvalues()[static_cast<long>(k)]);
    }
  }
  return bands;
}

TEST(QuasiperiodicSpectrum, RationalRatioGivesTheBlochBandsOfThePeriodicChain) {
  // β = p/q: a chain of N = 600 beads holds q bands with ~N/q modes each, at the Bloch bands of
  // the q-bead cell; only states bound to the two walls may sit in a gap (≤ 2 per gap).
  for (Kind kind : {Kind::s1, Kind::s2, Kind::cylinders})
    for (auto [p, q] : {std::pair<int, int>{1, 3}, {2, 5}}) {
      const std::size_t n = 600;
      const Chain c = quasi(kind, 0.6, static_cast<double>(p) / q, n).chain(0);
      const auto bands = bloch_bands(c, static_cast<std::size_t>(q));
      for (std::size_t k = 0; k + 1 < bands.size(); ++k)
        ASSERT_LT(bands[k].second, bands[k + 1].first) << "no gap between Bloch bands " << k << " and " << k + 1;
      const auto w = omega2(c);
      std::vector<int> in_band(bands.size(), 0);
      int in_gap = 0;
      const double tol = 1e-9 * w.back();
      for (double x : w) {
        bool found = false;
        for (std::size_t k = 0; k < bands.size(); ++k)
          if (x >= bands[k].first - tol && x <= bands[k].second + tol) ++in_band[k], found = true;
        if (!found) ++in_gap;
      }
      EXPECT_LE(in_gap, 2 * (q - 1)) << to_string(kind) << " " << p << "/" << q;
      for (int count : in_band)
        EXPECT_LE(std::abs(count - static_cast<int>(n) / q), 2) << to_string(kind) << " " << p << "/" << q;
      // Count the gaps of the finite chain's spectrum directly: every Bloch gap wider than 40 typical
      // spacings (at λ = 0.6 at least one; the cylinders' bond modulation opens narrower gaps than
      // the on-site ones) shows as a spacing wider than 20 (edge states split it in two at most).
      const double typical = (w.back() - w.front()) / static_cast<double>(n);
      int wide = 0, open = 0;
      for (std::size_t j = 1; j < w.size(); ++j) wide += w[j] - w[j - 1] > 20 * typical;
      for (std::size_t k = 0; k + 1 < bands.size(); ++k) open += bands[k + 1].first - bands[k].second > 40 * typical;
      EXPECT_GE(open, 1) << to_string(kind);
      EXPECT_GE(wide, open) << to_string(kind);
      EXPECT_LE(wide, 3 * (q - 1)) << to_string(kind);
    }
}

double mean_ipr_times_n(const ChainRecipe& r) {
  double sum = 0;
  const auto s = spectrum(dynamical_matrix(r.chain(0)), all_modes(), {.method = SpectrumMethod::fast});
  for (double p : s.ipr) sum += p;
  return sum / static_cast<double>(s.size()) * static_cast<double>(r.N);
}

TEST(QuasiperiodicSpectrum, S1HasTheAubryAndreTransitionAtLambdaK0EqualsTwoK) {
  // k0 = 4K: the transition sits at λ = 0.5. Below it the modes are extended (mean IPR·N does not
  // grow with N); above it localized (mean IPR·N grows ∝ N).
  const auto growth = [](double lambda) {
    return mean_ipr_times_n(quasi(Kind::s1, lambda, golden_mean, 1597)) /
           mean_ipr_times_n(quasi(Kind::s1, lambda, golden_mean, 377));
  };
  EXPECT_LT(growth(0.3), 1.3);
  EXPECT_LT(growth(0.4), 1.3);
  EXPECT_GT(growth(0.6), 3.0);
  EXPECT_GT(growth(0.8), 3.5);
}

TEST(QuasiperiodicSpectrum, S1LocalizationLengthIsTheAubryAndreValue) {
  // Above the transition every mode decays at the rate γ = ln(λ k0 / 2K), whatever its frequency.
  // γ from the recursion −K u_{n+1} − K u_{n−1} + (2K + k_n − m ω²) u_n = 0 over 2·10⁵ sites, at
  // eigenfrequencies of a 610-bead chain, renormalizing as it goes.
  for (double lambda : {0.7, 0.9}) {
    ChainRecipe r = quasi(Kind::s1, lambda, golden_mean, 610);
    const Chain c = r.chain(0);
    const double K = linear_stiffness(c.contact[1], c.precompression), k0 = r.as<Quasiperiodic>()->k0 * K, m = c.mass[0];
    const auto w = omega2(c);
    for (std::size_t j : {50, 200, 300, 450}) {
      double u0 = 0, u1 = 1, log_growth = 0;
      const std::size_t steps = 200000;
      for (std::size_t n = 1; n <= steps; ++n) {
        const double kn = k0 * (1 + lambda * std::cos(2 * pi * golden_mean * static_cast<double>(n) + 0.4));
        const double u2 = ((2 * K + kn - m * w[j]) * u1 - K * u0) / K;
        u0 = u1, u1 = u2;
        const double size = std::hypot(u0, u1);
        log_growth += std::log(size);
        u0 /= size, u1 /= size;
      }
      EXPECT_NEAR(log_growth / steps, std::log(lambda * r.as<Quasiperiodic>()->k0 / 2), 0.01) << lambda << " mode " << j;
    }
  }
}

TEST(QuasiperiodicSpectrum, GapsAreLabelledByMultiplesOfTheRatio) {
  // Gap labelling: in every gap of a quasiperiodic chain the integrated density of states (modes
  // below / N) is {nβ} mod 1 for some integer n. The four widest gaps of N = 2000 beads, to 3/N.
  const std::size_t n = 2000;
  for (Kind kind : {Kind::s1, Kind::s2, Kind::cylinders}) {
    const auto w = omega2(quasi(kind, 0.4, golden_mean, n).chain(0));
    std::vector<std::pair<double, std::size_t>> gaps;
    for (std::size_t j = 1; j < n; ++j) gaps.emplace_back(w[j] - w[j - 1], j);
    std::sort(gaps.rbegin(), gaps.rend());
    for (std::size_t g = 0; g < 4; ++g) {
      const double idos = static_cast<double>(gaps[g].second) / static_cast<double>(n);
      double nearest = 1;
      for (int m = -30; m <= 30; ++m) {
        const double label = static_cast<double>(m) * golden_mean - std::floor(static_cast<double>(m) * golden_mean);
        nearest = std::min({nearest, std::fabs(idos - label), 1 - std::fabs(idos - label)});
      }
      EXPECT_LT(nearest, 3.0 / static_cast<double>(n)) << to_string(kind) << " gap at IDOS " << idos;
    }
  }
}

/// Mean IPR·N of the modes in [lo, hi) of the spectrum (fractions of N, by mode number).
double band_ipr_times_n(const ChainRecipe& r, double lo, double hi) {
  const auto s = spectrum(dynamical_matrix(r.chain(0)), all_modes(), {.method = SpectrumMethod::fast});
  const auto n = static_cast<double>(s.size());
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t j = static_cast<std::size_t>(lo * n); j < static_cast<std::size_t>(hi * n); ++j, ++count)
    sum += s.ipr[j];
  return sum / static_cast<double>(count) * n;
}

TEST(QuasiperiodicSpectrum, CylindersHaveNoAubryAndreTransition) {
  // Bond-only modulation: no λ at which every mode localizes at once. Up to λ = 0.9 (α0 = 45°:
  // angles 4.5°…85.5°) the lower 60% of the spectrum stays extended (IPR·N independent of N), while
  // S1 past its transition localizes every part of its spectrum. (The toolkit finds the upper
  // modes of C localized above λ ≈ 0.6: a mobility edge, docs/physics.md.)
  const auto growth = [](Kind kind, double lambda, double lo, double hi) {
    ChainRecipe small = quasi(kind, lambda, golden_mean, 377), large = small;
    large.N = 1597;
    return band_ipr_times_n(large, lo, hi) / band_ipr_times_n(small, lo, hi);
  };
  for (double lambda : {0.3, 0.6, 0.9}) EXPECT_LT(growth(Kind::cylinders, lambda, 0, 0.6), 1.15) << lambda;
  EXPECT_LT(growth(Kind::cylinders, 0.5, 0, 1), 1.15);
  for (double lo : {0.0, 0.3, 0.6}) EXPECT_GT(growth(Kind::s1, 0.7, lo, lo + 0.3), 3.0) << lo;
}

}  // namespace
}  // namespace granular
