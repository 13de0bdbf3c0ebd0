// Covariant Lyapunov vectors (covariant_vectors.hpp) on the chaotic little Hertz chain of the
// Lyapunov spectrum's tests: the tangent map carries each CLV onto itself, their growth rates are
// the exponents of the same orbit, and they have the structure the theory fixes (k = 1: the first
// Gram–Schmidt vector; a symplectic map: CLV_i and CLV_j are symplectically orthogonal unless
// λ_i + λ_j = 0).
#include "granular/chaos/covariant_vectors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/dynamics_fixtures.hpp"
#include "granular/chaos/alignment_indices.hpp"
#include "granular/chaos/lyapunov_spectrum.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

constexpr double clv_unit = 1e-6;  // t_unit of the norm [s]

// 8 beads at 0.01 N kicked at 0.05 m/s: contacts open and close, λ_1 ≈ 3700/s (as in
// lyapunov_spectrum_test.cpp).
struct ClvChain {
  Chain chain = fixtures::anderson(8, 0.01);
  ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  State start = velocity_kick(chain, 2, 0.05);
  double tau = 1e-7;
};

double clv_dot(const State& a, const State& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.u.size(); ++i) s += a.u[i] * b.u[i] + clv_unit * clv_unit * a.v[i] * b.v[i];
  return s;
}

// The sine of the angle between two vectors in (δu, t_unit δv): ‖â − (â·b̂) b̂‖, accurate when small.
double clv_sine(const State& a, const State& b) {
  const double na = std::sqrt(clv_dot(a, a)), nb = std::sqrt(clv_dot(b, b)), c = clv_dot(a, b) / (na * nb);
  double s = 0;
  for (std::size_t i = 0; i < a.u.size(); ++i) {
    const double du = a.u[i] / na - c * b.u[i] / nb, dv = clv_unit * (a.v[i] / na - c * b.v[i] / nb);
    s += du * du + dv * dv;
  }
  return std::sqrt(s);
}
// The symplectic product Ω(a, b) = Σ m_n (δu_a δv_b − δv_a δu_b) of two vectors, each scaled to unit
// length in coordinates where Ω is the standard form (x = √m δu / t_unit, y = √m δv): in [−1, 1].
double clv_symplectic(const Chain& chain, const State& a, const State& b) {
  double omega = 0, na = 0, nb = 0;
  for (std::size_t i = 0; i < a.u.size(); ++i) {
    const double m = chain.mass[i];
    omega += m * (a.u[i] * b.v[i] - a.v[i] * b.u[i]) / clv_unit;
    na += m * (a.u[i] * a.u[i] / (clv_unit * clv_unit) + a.v[i] * a.v[i]);
    nb += m * (b.u[i] * b.u[i] / (clv_unit * clv_unit) + b.v[i] * b.v[i]);
  }
  return omega / std::sqrt(na * nb);
}

// e_c of (δu, t_unit δv) on n beads, times x.
State clv_unit_vector(std::size_t n, std::size_t c, double x = 1) {
  State w(n);
  if (c < n) w.u[c] = x;
  else w.v[c - n] = x / clv_unit;
  return w;
}

// The CLVs at 0, 0.2 and 0.4 ms after a 5 ms transient, each carried 2000 steps by a fresh
// tangent map from the orbit's state: the image of CLV_i(t) has the direction of CLV_i(t + Δ), to
// a sine of at most 1e-8 (measured: 7e-14). Covariance holds by construction whatever C has
// converged to, so this checks that the stored R's, Q's and samples belong together. The
// Gram–Schmidt vectors beyond the first are not covariant (sine 0.1 … 1 measured).
TEST(CovariantVectors, TheTangentMapCarriesEachClvOntoItsDirectionLater) {
  const ClvChain c;
  const std::size_t n = c.chain.size(), k = 2 * n;
  const CovariantVectorsConfig config{.vectors = k,
                                      .orthonormalize_every = 100,
                                      .forward_transient = 50000,
                                      .backward_transient = 50000};
  const CovariantVectors clv = covariant_vectors(c.law, c.chain, saba2c(), c.tau, c.start, config, {0, 2000, 4000});
  ASSERT_EQ(clv.vectors.size(), 3u);
  EXPECT_EQ(clv.steps, (std::vector<std::uint64_t>{50000, 52000, 54000}));
  EXPECT_NEAR(clv.time[1], 52000 * c.tau, 1e-15);
  // The orbit is the Lyapunov spectrum's advanced by the same calls, bit for bit.
  LyapunovSpectrum gs(c.law, c.chain, saba2c(), c.tau, c.start, {.vectors = k, .orthonormalize_every = 100});
  gs.advance(50000);
  EXPECT_EQ(fixtures::relative_difference(gs.state().u, clv.orbit[0].u), 0.0);
  const std::vector<State> gs0 = gs.vectors();
  gs.advance(2000);
  EXPECT_EQ(fixtures::relative_difference(gs.state().v, clv.orbit[1].v), 0.0);
  const std::vector<State> gs1 = gs.vectors();

  double worst = 0;
  for (std::size_t s = 0; s + 1 < 3; ++s) {
    auto map = make_tangent_propagator(c.law, c.chain, saba2c(), c.tau, clv.orbit[s], clv.vectors[s],
                                       {.enabled = true, .renormalize_every = 0});
    map->advance(2000);
    EXPECT_EQ(fixtures::relative_difference(map->displacement(), clv.orbit[s + 1].u), 0.0);
    for (std::size_t i = 0; i < k; ++i) worst = std::max(worst, clv_sine(map->deviation(i), clv.vectors[s + 1][i]));
  }
  auto map = make_tangent_propagator(c.law, c.chain, saba2c(), c.tau, clv.orbit[0], gs0,
                                     {.enabled = true, .renormalize_every = 0});
  map->advance(2000);
  double first = clv_sine(map->deviation(0), gs1[0]), others = 1;
  for (std::size_t i = 1; i < k; ++i) others = std::min(others, clv_sine(map->deviation(i), gs1[i]));
  std::printf("  largest sine(M CLV_i(t), CLV_i(t + 0.2 ms)) %.1e; Gram-Schmidt: first %.1e, others >= %.1e\n", worst,
              first, others);
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(first, 1e-12);  // CLV_1 is the first Gram–Schmidt vector
  EXPECT_GT(others, 1e-3);  // the test tells covariant vectors from others
}

// Over a window of W = 20 ms (λ_1 W ≈ 77) between 5 ms transients. Exactly, span(CLV_1 … CLV_j) is
// span(Q_1 … Q_j), so W Σ_{i≤j} (γ_i − λ_i) = ln G_j(t0) − ln G_j(t1), with G_j the volume
// (GALI_j) of the unit CLV_1 … CLV_j and λ_i the Gram–Schmidt exponents of the window: checked to
// 1e-9 λ_1 W (rounding). That volume term is the finite-time difference between the growth rates
// and the exponents; measured here at most 141/s, 3.7 % of λ_1 (the test allows 10 %).
TEST(CovariantVectors, TheGrowthRatesAreTheExponentsOfTheSameOrbit) {
  const ClvChain c;
  const std::size_t n = c.chain.size(), k = 2 * n;
  const CovariantVectors clv = covariant_vectors(
      c.law, c.chain, saba2c(), c.tau, c.start,
      {.vectors = k, .orthonormalize_every = 100, .forward_transient = 50000, .backward_transient = 50000}, {0, 200000});
  LyapunovSpectrum gs(c.law, c.chain, saba2c(), c.tau, c.start, {.vectors = k, .orthonormalize_every = 100});
  gs.advance(50000);
  const std::vector<double> before = gs.exponents();
  const double t0 = gs.time();
  gs.advance(200000);
  const std::vector<double> after = gs.exponents();
  const double t1 = gs.time(), window = t1 - t0;
  std::vector<double> lambda(k);
  for (std::size_t i = 0; i < k; ++i) lambda[i] = (after[i] * t1 - before[i] * t0) / window;
  const double top = lambda.front();
  ASSERT_GT(top, 1000.0);
  const std::vector<double> g0 = generalized_alignment_indices(clv.vectors[0]),
                            g1 = generalized_alignment_indices(clv.vectors[1]);
  double worst = 0, identity = 0, sum_growth = 0, sum_lambda = 0;
  std::printf("  growth rate / exponent over the window [1/s]:");
  for (std::size_t i = 0; i < k; ++i) {
    std::printf(" %.0f/%.0f", clv.growth_rates[i], lambda[i]);
    EXPECT_NEAR(clv.exponents[i], lambda[i], 1e-9 * top) << i;  // the stored R's are the run's
    worst = std::max(worst, std::abs(clv.growth_rates[i] - lambda[i]));
    sum_growth += clv.growth_rates[i];
    sum_lambda += lambda[i];
    const double volume = i == 0 ? 0.0 : std::log(g0[i - 1]) - std::log(g1[i - 1]);
    identity = std::max(identity, std::abs(window * (sum_growth - sum_lambda) - volume));
  }
  std::printf("\n  largest difference %.0f /s (lambda_1 %.0f /s); volume identity off by %.1e\n", worst, top, identity);
  EXPECT_LT(identity, 1e-9 * top * window);
  EXPECT_LT(worst, 0.1 * top);
  EXPECT_NEAR(clv.growth_rates.front(), lambda.front(), 1e-9 * top);  // CLV_1 = Q_1
}

// k = 1: C is a 1 × 1 matrix, so the CLV is the single Gram–Schmidt vector of the same run (to
// sign) and its growth rate that vector's exponent.
TEST(CovariantVectors, ForOneVectorTheClvIsTheGramSchmidtVector) {
  const ClvChain c;
  const CovariantVectors clv = covariant_vectors(
      c.law, c.chain, saba2c(), c.tau, c.start,
      {.vectors = 1, .orthonormalize_every = 50, .forward_transient = 20000, .backward_transient = 1000}, {0, 30000});
  LyapunovSpectrum gs(c.law, c.chain, saba2c(), c.tau, c.start, {.vectors = 1, .orthonormalize_every = 50});
  gs.advance(20000);
  EXPECT_LT(clv_sine(clv.vectors[0][0], gs.vectors()[0]), 1e-14);
  const double s0 = gs.exponents()[0] * gs.time(), t0 = gs.time();
  gs.advance(30000);
  EXPECT_LT(clv_sine(clv.vectors[1][0], gs.vectors()[0]), 1e-14);
  const double lambda = (gs.exponents()[0] * gs.time() - s0) / (gs.time() - t0);
  EXPECT_NEAR(clv.growth_rates[0], lambda, 1e-9 * std::abs(lambda));
  EXPECT_TRUE(clv.split_angles[0].empty());
  EXPECT_GE(clv.participation[0][0], 1.0);
  EXPECT_LE(clv.participation[0][0], 8.0);
}

// The map preserves Ω, so Ω(CLV_i, CLV_j) of the unit vectors changes in time as
// exp(−(λ_i + λ_j) t) and must vanish unless λ_i + λ_j = 0 (i + j = 2N + 1, the pair ±λ): exact
// CLVs are symplectically orthogonal to all but their partner. Ours reach it as
// exp(−|λ_i + λ_j| T), T the forward stretch before the sample (expanding pairs, through Q) or the
// backward one after it (contracting pairs, through C); with T = 15 ms, pairs with |λ_i + λ_j| T ≥
// 25 have |Ω| ≤ 1e-8 (measured: at most 1.1e-12 over 77 pairs); the partners' |Ω| is 9e-4 … 3e-2.
TEST(CovariantVectors, EachClvIsSymplecticallyOrthogonalToAllButItsPartner) {
  const ClvChain c;
  const std::size_t n = c.chain.size(), k = 2 * n;
  const double stretch = 150000 * c.tau;
  const CovariantVectors clv = covariant_vectors(
      c.law, c.chain, saba2c(), c.tau, c.start,
      {.vectors = k, .orthonormalize_every = 100, .forward_transient = 150000, .backward_transient = 150000}, {0});
  const std::vector<State>& v = clv.vectors[0];
  // The exponents: the growth rates over the empty window are zero; the forward run's.
  LyapunovSpectrum gs(c.law, c.chain, saba2c(), c.tau, c.start, {.vectors = k, .orthonormalize_every = 100});
  gs.advance(300000);
  const std::vector<double> lambda = gs.exponents();
  double worst = 0, partner = 1;
  std::size_t tested = 0;
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j) {
      const double omega = std::abs(clv_symplectic(c.chain, v[i], v[j]));
      if (i + j == k - 1) partner = std::min(partner, omega);
      else if (std::abs(lambda[i] + lambda[j]) * stretch >= 25) {
        worst = std::max(worst, omega);
        ++tested;
      }
    }
  std::printf("  %zu pairs: largest |Omega| %.1e; partners' smallest %.1e\n", tested, worst, partner);
  EXPECT_GT(tested, 60u);
  EXPECT_LT(worst, 1e-8);
  EXPECT_GT(partner, 1e-6);
}

// The angles and the localization as the header defines them, from the CLVs themselves: the
// split angles (computed in Q's coordinates) against smallest_subspace_angle of the two sets, the
// participation and centre against the per-bead shares of ‖w‖². The angles agree to 2e-14
// relative (the smallest 1.5e-3 rad).
TEST(CovariantVectors, TheAnglesAndTheLocalizationAreTheVectorsOwn) {
  const ClvChain c;
  const std::size_t n = c.chain.size(), k = 2 * n;
  const CovariantVectors clv = covariant_vectors(
      c.law, c.chain, saba2c(), c.tau, c.start,
      {.vectors = k, .orthonormalize_every = 100, .forward_transient = 50000, .backward_transient = 20000}, {0});
  const std::vector<State>& v = clv.vectors[0];
  ASSERT_EQ(clv.split_angles[0].size(), k - 1);
  double worst = 0, smallest = 1;
  for (std::size_t j = 1; j < k; ++j) {
    const std::vector<State> first(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(j)),
        rest(v.begin() + static_cast<std::ptrdiff_t>(j), v.end());
    const double angle = smallest_subspace_angle(first, rest);
    worst = std::max(worst, std::abs(angle - clv.split_angles[0][j - 1]) / angle);
    smallest = std::min(smallest, angle);
  }
  std::printf("  split angles: smallest %.1e rad, largest relative difference %.1e\n", smallest, worst);
  EXPECT_LT(worst, 1e-6);
  for (std::size_t i = 0; i < k; ++i) {
    const double norm = clv_dot(v[i], v[i]);
    double sum_p2 = 0, centre = 0;
    EXPECT_NEAR(norm, 1.0, 1e-13);
    for (std::size_t b = 0; b < n; ++b) {
      const double p = (v[i].u[b] * v[i].u[b] + clv_unit * clv_unit * v[i].v[b] * v[i].v[b]) / norm;
      sum_p2 += p * p;
      centre += static_cast<double>(b) * p;
    }
    EXPECT_NEAR(clv.participation[0][i], 1 / sum_p2, 1e-12) << i;
    EXPECT_NEAR(clv.centre[0][i], centre, 1e-12) << i;
  }
}

TEST(CovariantVectors, TheSmallestSubspaceAngleHasTheClosedForms) {
  const std::size_t n = 3;
  for (const double theta : {0.3, 1e-10, std::numbers::pi / 2}) {
    State b = clv_unit_vector(n, 0, std::cos(theta));
    b.v[1] = std::sin(theta) / clv_unit;  // in the plane of δu_0 and δv_1
    EXPECT_NEAR(smallest_subspace_angle({clv_unit_vector(n, 0)}, {b}), theta, 1e-16 + 1e-14 * theta) << theta;
  }
  // The plane of δu_0 and δu_1 (any basis) and a vector at 0.2 rad to it beside one orthogonal.
  State b = clv_unit_vector(n, 1, std::cos(0.2));
  b.u[2] = std::sin(0.2);
  State skew = clv_unit_vector(n, 0, 2);
  skew.u[1] = 3;
  EXPECT_NEAR(smallest_subspace_angle({clv_unit_vector(n, 0), skew}, {b, clv_unit_vector(n, 5)}), 0.2, 1e-14);
  EXPECT_NEAR(smallest_subspace_angle({clv_unit_vector(n, 2)}, {clv_unit_vector(n, 3), clv_unit_vector(n, 4)}),
              std::numbers::pi / 2, 1e-15);
  EXPECT_THROW(smallest_subspace_angle({clv_unit_vector(n, 0), clv_unit_vector(n, 0, 2)}, {b}), InvalidInput);
  EXPECT_THROW(smallest_subspace_angle({}, {b}), InvalidInput);
}

TEST(CovariantVectors, RefusesWhatCannotBeRunOrKept) {
  const ClvChain c;
  const auto run = [&c](const CovariantVectorsConfig& config, const std::vector<std::uint64_t>& samples) {
    return covariant_vectors(c.law, c.chain, saba2c(), c.tau, c.start, config, samples);
  };
  const auto parameter = [&run](const CovariantVectorsConfig& config, const std::vector<std::uint64_t>& samples) {
    try {
      run(config, samples);
    } catch (const InvalidInput& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  EXPECT_EQ(parameter({.vectors = 0}, {0}), "vectors");
  EXPECT_EQ(parameter({.vectors = 17}, {0}), "vectors");
  EXPECT_EQ(parameter({.orthonormalize_every = 0}, {0}), "orthonormalize_every");
  EXPECT_EQ(parameter({.time_unit = 0}, {0}), "time_unit");
  EXPECT_EQ(parameter({.memory_limit = -1}, {0}), "memory_limit");
  EXPECT_EQ(parameter({}, {}), "sample_steps");
  EXPECT_EQ(parameter({}, {20, 10}), "sample_steps");
  // 16 vectors, 10^4 QRs of 136 doubles: 1.1e7 bytes of R's, over a limit of 1e6.
  CovariantVectorsConfig config{.vectors = 16,
                                .orthonormalize_every = 10,
                                .forward_transient = 0,
                                .backward_transient = 50000,
                                .memory_limit = 1e6};
  EXPECT_EQ(parameter(config, {0, 50000}), "sample_steps");
  config.backward_transient = 100;
  const CovariantVectors clv = run(config, {0, 0, 100});  // a repeated sample is the same
  EXPECT_LT(clv.stored_bytes, 1e6);
  EXPECT_GE(clv.stored_bytes, 8.0 * 136 * 20);  // 20 R's
  ASSERT_EQ(clv.vectors.size(), 3u);
  EXPECT_EQ(fixtures::relative_difference(clv.vectors[0][15].u, clv.vectors[1][15].u), 0.0);
}

}  // namespace
}  // namespace granular
