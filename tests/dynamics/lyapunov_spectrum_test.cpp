// Several deviation vectors through the tangent map (tangent_map.hpp) and the Lyapunov spectrum
// they give (lyapunov_spectrum.hpp): the orbit is the plain run's bit for bit, each further vector
// is what the single-vector map makes of it, the map is symplectic, and the full spectrum of a
// small Hertz chain whose contacts open has the structure of a Hamiltonian one (pairs ±λ, two
// zeros, sum zero).
#include "granular/dynamics/lyapunov_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics_fixtures.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

using fixtures::relative_difference;

// A strongly nonlinear little chain: 8 beads at 0.01 N, kicked at 0.05 m/s so that contacts open
// and close (the velocity kick's energy is far above every bond's static energy).
struct SmallChain {
  Chain chain = fixtures::anderson(8, 0.01);
  ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  State start = velocity_kick(chain, 2, 0.05);
  double tau = 1e-7;
};

State pattern(std::size_t n, double phase) {
  State w(n);
  for (std::size_t i = 0; i < n; ++i) {
    w.u[i] = std::sin(1.7 * static_cast<double>(i) + phase);
    w.v[i] = 1e6 * std::cos(0.9 * static_cast<double>(i) + 2 * phase);
  }
  return w;
}

TEST(LyapunovSpectrum, TheOrbitIsThePlainRunsBitForBit) {
  const SmallChain s;
  for (const SplittingScheme& scheme : {saba2c(), aba864()}) {
    LyapunovSpectrum spectrum(s.law, s.chain, scheme, s.tau, s.start, {.vectors = 5, .orthonormalize_every = 7});
    spectrum.advance(1000);
    // The plain run on the whole chain (the map has no active window), advanced by the same call.
    const auto plain =
        fixtures::run(make_splitting_propagator(s.law, s.chain, scheme, s.tau, s.start, {.enabled = false}), 1000);
    const State a = spectrum.state();
    EXPECT_EQ(relative_difference(a.u, plain->displacement()), 0.0) << scheme.name;
    EXPECT_EQ(relative_difference(a.v, plain->velocity()), 0.0) << scheme.name;
  }
}

// Each further vector goes through the same expressions as the single-vector map's fused kernels.
TEST(LyapunovSpectrum, EachFurtherVectorIsWhatTheSingleVectorMapMakesOfIt) {
  const SmallChain s;
  const std::vector<State> w{pattern(8, 0.1), pattern(8, 0.5), pattern(8, 1.3)};
  for (const SplittingScheme& scheme : {saba2c(), aba864()}) {
    auto several =
        make_tangent_propagator(s.law, s.chain, scheme, s.tau, s.start, w, {.enabled = true, .renormalize_every = 0});
    several->advance(500);
    ASSERT_EQ(several->deviation_count(), 3u);
    for (std::size_t j = 0; j < w.size(); ++j) {
      auto one = make_tangent_propagator(s.law, s.chain, scheme, s.tau, s.start, w[j],
                                         {.enabled = true, .renormalize_every = 0});
      one->advance(500);
      EXPECT_EQ(relative_difference(several->deviation_displacement(j), one->deviation_displacement()), 0.0)
          << scheme.name << " vector " << j;
      EXPECT_EQ(relative_difference(several->deviation_velocity(j), one->deviation_velocity()), 0.0)
          << scheme.name << " vector " << j;
      EXPECT_GT(relative_difference(several->deviation_displacement(j), w[j].u), 0.1);  // it moved
    }
  }
}

// M of 2000 steps (0.2 ms, contacts opening) from the 2N unit vectors, in coordinates where the
// symplectic form Σ m_i du_i ∧ dv_i is the standard one: x = √m ω_s δu, y = √m δv (ω_s = 1e6/s).
TEST(LyapunovSpectrum, TheTangentMapIsSymplectic) {
  const SmallChain s;
  const std::size_t n = s.chain.size();
  const double omega = 1e6;
  std::vector<double> scale(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const double root_m = 1 / std::sqrt(s.chain.inverse_mass[i]);
    scale[i] = root_m * omega;
    scale[n + i] = root_m;
  }
  std::vector<State> basis(2 * n, State(n));
  for (std::size_t c = 0; c < 2 * n; ++c) (c < n ? basis[c].u[c] : basis[c].v[c - n]) = 1 / scale[c];
  for (const SplittingScheme& scheme : {saba2c(), aba864()}) {
    auto map = make_tangent_propagator(s.law, s.chain, scheme, s.tau, s.start, basis,
                                       {.enabled = true, .renormalize_every = 0});
    map->advance(2000);
    std::vector<double> m(4 * n * n);  // M[r][c], scaled
    double largest = 0;
    for (std::size_t c = 0; c < 2 * n; ++c) {
      const auto du = map->deviation_displacement(c), dv = map->deviation_velocity(c);
      for (std::size_t r = 0; r < n; ++r) {
        m[r * 2 * n + c] = scale[r] * du[r];
        m[(n + r) * 2 * n + c] = scale[n + r] * dv[r];
      }
    }
    for (double x : m) largest = std::max(largest, std::abs(x));
    // (Mᵀ J M)_{ab} = Σ_i M_{i a} M_{n+i, b} − M_{n+i, a} M_{i b}
    double worst = 0;
    for (std::size_t a = 0; a < 2 * n; ++a)
      for (std::size_t b = 0; b < 2 * n; ++b) {
        double x = 0;
        for (std::size_t i = 0; i < n; ++i)
          x += m[i * 2 * n + a] * m[(n + i) * 2 * n + b] - m[(n + i) * 2 * n + a] * m[i * 2 * n + b];
        const double j = (b == a + n) ? 1.0 : (a == b + n) ? -1.0 : 0.0;
        worst = std::max(worst, std::abs(x - j));
      }
    std::printf("  %s: max |M^T J M - J| = %.2e, max |M| = %.2e\n", scheme.name.c_str(), worst, largest);
    EXPECT_GT(largest, 2.0);  // M is far from the identity: the test is not trivial
    EXPECT_LT(worst, 1e-12 * largest * largest);
  }
}

// The 2N exponents of a Hamiltonian flow come in pairs λ_j = −λ_{2N+1−j} (the map is symplectic),
// two of them zero (the direction of the flow and the gradient of the energy, both kept), and
// their sum is the volume growth, zero. Finite-time values approach that as ~1/t; the test's
// error is how much the exponents still move between T/2 and T (measured 235/s for λ_1 ≈ 3700/s
// at T = 64 ms; the pairs then agree within 95/s, the zeros are ±91/s and shrink as ln t / t).
TEST(LyapunovSpectrum, TheFullSpectrumOfASmallHertzChainIsHamiltonian) {
  const SmallChain s;
  const std::size_t n = s.chain.size();
  LyapunovSpectrum spectrum(s.law, s.chain, saba2c(), s.tau, s.start, {.vectors = 2 * n, .orthonormalize_every = 10});
  spectrum.advance(320000);  // T/2 = 32 ms: λ_1 T/2 ≈ 120 e-foldings
  const std::vector<double> half = spectrum.exponents();
  spectrum.advance(320000);
  const std::vector<double> l = spectrum.exponents();
  double error = 0, sum = 0;
  for (std::size_t j = 0; j < l.size(); ++j) {
    error = std::max(error, std::abs(l[j] - half[j]));
    sum += l[j];
  }
  std::printf("  lambda(T = %.3f s) [1/s]:", spectrum.time());
  for (double x : l) std::printf(" %.0f", x);
  std::printf("\n  finite-time error (largest change since T/2) %.0f /s; sum %.3e /s\n", error, sum);
  const double top = l.front();
  EXPECT_GT(top, 10 * error);  // clearly chaotic: contacts open and close
  for (std::size_t j = 0; j + 1 < l.size(); ++j) EXPECT_GE(l[j] + error, l[j + 1]) << j;  // ordered by QR
  for (std::size_t j = 0; j < n; ++j) EXPECT_LT(std::abs(l[j] + l[2 * n - 1 - j]), error) << "pair " << j;
  EXPECT_LT(std::abs(l[n - 1]), error);  // two zeros
  EXPECT_LT(std::abs(l[n]), error);
  EXPECT_LT(std::abs(sum), 1e-12 * top);  // det M = 1 to rounding: 1e-14 relative measured
}

TEST(LyapunovSpectrum, RefusesImpossibleCounts) {
  const SmallChain s;
  EXPECT_THROW(LyapunovSpectrum(s.law, s.chain, saba2c(), s.tau, s.start, {.vectors = 0}), InvalidInput);
  EXPECT_THROW(LyapunovSpectrum(s.law, s.chain, saba2c(), s.tau, s.start, {.vectors = 17}), InvalidInput);
  EXPECT_THROW(LyapunovSpectrum(s.law, s.chain, saba2c(), s.tau, s.start, {.vectors = 2, .orthonormalize_every = 0}),
               InvalidInput);
}

}  // namespace
}  // namespace granular
