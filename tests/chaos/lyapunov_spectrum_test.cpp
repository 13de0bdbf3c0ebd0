// Several deviation vectors through the tangent map (tangent_map.hpp) and the Lyapunov spectrum
// they give (lyapunov_spectrum.hpp): the orbit is the plain run's bit for bit, each further vector
// is what the single-vector map makes of it, the map is symplectic, and the full spectrum of a
// small Hertz chain whose contacts open has the structure of a Hamiltonian one (pairs ±λ, two
// zeros, sum zero).
#include "granular/chaos/lyapunov_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <span>
#include <vector>

#include <gtest/gtest.h>
#include <boost/numeric/odeint.hpp>

#include "dynamics/dynamics_fixtures.hpp"
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

// An independent integration: the orbit and its variational equations written out here for the
// Hertz law (δu' = δv, m δv' = −∂²V δu, the bond stiffness K_k = f_k'(x_k)), integrated by
// Boost.Odeint's controlled RKF78 at 1e-12 and re-orthonormalized by modified Gram–Schmidt every
// microsecond. Scaled state: u/ℓ, v t_u/ℓ (ℓ = 1e-6 m, t_u = 1 µs), deviations (δu, t_u δv).
struct VariationalHertz {
  HertzLaw::View law;
  const std::vector<double>* im;
  std::size_t n, k;
  static constexpr double length = 1e-6, unit = 1e-6;
  void operator()(const std::vector<double>& y, std::vector<double>& dy, double) const {
    std::vector<double> f(n + 1), stiff(n + 1);
    const auto u = [&](std::ptrdiff_t b) { return b < 0 || b >= static_cast<std::ptrdiff_t>(n) ? 0.0 : y[b]; };
    for (std::size_t b = 0; b <= n; ++b) {
      const auto i = static_cast<std::ptrdiff_t>(b);
      law.force_stiffness(b, length * (u(i - 1) - u(i)), f[b], stiff[b]);
    }
    for (std::size_t i = 0; i < n; ++i) {
      dy[i] = y[n + i] / unit;
      dy[n + i] = unit / length * (*im)[i] * (f[i] - f[i + 1]);
    }
    for (std::size_t j = 0; j < k; ++j) {
      const double* w = y.data() + 2 * n * (j + 1);
      double* dw = dy.data() + 2 * n * (j + 1);
      const auto du = [&](std::ptrdiff_t b) { return b < 0 || b >= static_cast<std::ptrdiff_t>(n) ? 0.0 : w[b]; };
      for (std::size_t i = 0; i < n; ++i) {
        const auto b = static_cast<std::ptrdiff_t>(i);
        dw[i] = w[n + i] / unit;
        dw[n + i] = unit * (*im)[i] * (stiff[i] * (du(b - 1) - du(b)) - stiff[i + 1] * (du(b) - du(b + 1)));
      }
    }
  }
};

// The finite-time spectrum is a property of the orbit and the starting vectors, not of the scheme:
// from the same vectors, SABA2C at 0.1 µs (QR every 10 steps) and RKF78 at 1e-12 (Gram–Schmidt
// every µs) agree while their orbits still track the same true one. At T = 1.5 ms (λ_1 T ≈ 8) the
// largest difference of the 16 exponents was 4.3/s, 0.08 % of λ_1 = 5434/s; the test allows 1 %.
TEST(LyapunovSpectrum, TheFullSpectrumEqualsAnIndependentRkf78IntegrationOfTheVariationalEquations) {
  const SmallChain s;
  const std::size_t n = s.chain.size(), k = 2 * n;
  LyapunovSpectrum spectrum(s.law, s.chain, saba2c(), s.tau, s.start, {.vectors = k, .orthonormalize_every = 10});
  const std::vector<State> start = spectrum.vectors();
  const double T = 1.5e-3;
  spectrum.advance(static_cast<std::size_t>(std::llround(T / s.tau)));
  const std::vector<double> ours = spectrum.exponents();

  const VariationalHertz system{std::get<HertzLaw>(s.law).view(), &s.chain.inverse_mass, n, k};
  std::vector<double> y(2 * n * (k + 1));
  for (std::size_t i = 0; i < n; ++i) {
    y[i] = s.start.u[i] / VariationalHertz::length;
    y[n + i] = s.start.v[i] * VariationalHertz::unit / VariationalHertz::length;
  }
  for (std::size_t j = 0; j < k; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      y[2 * n * (j + 1) + i] = start[j].u[i];
      y[2 * n * (j + 1) + n + i] = start[j].v[i] * VariationalHertz::unit;
    }
  namespace odeint = boost::numeric::odeint;
  auto stepper = odeint::make_controlled(1e-12, 1e-12, odeint::runge_kutta_fehlberg78<std::vector<double>>());
  std::vector<double> sums(k, 0.0);
  const double interval = 1e-6;
  for (int step = 0; step < static_cast<int>(std::llround(T / interval)); ++step) {
    odeint::integrate_adaptive(stepper, system, y, step * interval, (step + 1) * interval, 1e-9);
    for (std::size_t j = 0; j < k; ++j) {  // modified Gram–Schmidt in (δu, t_u δv)
      double* w = y.data() + 2 * n * (j + 1);
      for (std::size_t i = 0; i < j; ++i) {
        const double* q = y.data() + 2 * n * (i + 1);
        double dot = 0;
        for (std::size_t c = 0; c < 2 * n; ++c) dot += q[c] * w[c];
        for (std::size_t c = 0; c < 2 * n; ++c) w[c] -= dot * q[c];
      }
      double norm = 0;
      for (std::size_t c = 0; c < 2 * n; ++c) norm += w[c] * w[c];
      norm = std::sqrt(norm);
      sums[j] += std::log(norm);
      for (std::size_t c = 0; c < 2 * n; ++c) w[c] /= norm;
    }
  }
  double worst = 0;
  std::printf("  lambda(T = %.1f ms) [1/s], SABA2C / RKF78:", T * 1e3);
  for (std::size_t j = 0; j < k; ++j) {
    const double theirs = sums[j] / T;
    std::printf(" %.0f/%.0f", ours[j], theirs);
    worst = std::max(worst, std::abs(ours[j] - theirs));
  }
  std::printf("\n  largest difference %.1f /s (lambda_1 %.0f /s)\n", worst, ours.front());
  EXPECT_GT(ours.front(), 1000.0);
  EXPECT_LT(worst, 0.01 * ours.front());
}

// Recording the R's (for covariant vectors) changes no arithmetic, and the R's are the run's: the
// sums of ln|R_jj| are the exponents' running sums.
TEST(LyapunovSpectrum, RecordingTheFactorsChangesNothing) {
  const SmallChain s;
  const std::size_t k = 4;
  LyapunovSpectrum plain(s.law, s.chain, saba2c(), s.tau, s.start, {.vectors = k, .orthonormalize_every = 7});
  LyapunovSpectrum recorded(s.law, s.chain, saba2c(), s.tau, s.start, {.vectors = k, .orthonormalize_every = 7});
  std::vector<double> sums(k, 0.0);
  std::size_t count = 0;
  recorded.record_factors([&](std::span<const double> r) {
    ASSERT_EQ(r.size(), k * k);
    for (std::size_t j = 0; j < k; ++j) {
      sums[j] += std::log(std::abs(r[j * k + j]));
      for (std::size_t i = j + 1; i < k; ++i) EXPECT_EQ(r[j * k + i], 0.0);  // upper triangular
    }
    ++count;
  });
  plain.advance(1000);
  recorded.advance(1000);
  EXPECT_EQ(count, 143u);  // every 7 steps, and once more at the end
  EXPECT_EQ(relative_difference(plain.state().u, recorded.state().u), 0.0);
  const std::vector<State> a = plain.vectors(), b = recorded.vectors();
  for (std::size_t j = 0; j < k; ++j) {
    EXPECT_EQ(relative_difference(a[j].u, b[j].u), 0.0);
    EXPECT_EQ(plain.exponents()[j], recorded.exponents()[j]);
    EXPECT_NEAR(sums[j], recorded.exponents()[j] * recorded.time(), 1e-12 * std::abs(sums[j]) + 1e-15);
  }
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
