// Breathers at F0 = 0 (docs/breathers.md, "Zero precompression: beads on springs"): a uniform
// chain of steel beads touching without precompression, each held by an on-site spring (S1 with
// λ = 0 and k0 in N/m: a Newton's cradle on springs). James, Kevrekidis & Cuevas, Physica D 251
// (2013) 39: such chains have breathers above the on-site frequency. Checked against what does
// not come from the shooting code: direct integration by the library's propagator, the
// small-amplitude asymptotics (the stationary discrete p-Schrödinger equation, solved here by its
// own Newton iteration), and the symplectic pairing of the multipliers.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "breather_fixtures.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/error.hpp"
#include "granular/orbits/breather_branch.hpp"
#include "scratch.hpp"

namespace granular {
namespace {

constexpr double cradle_spring = 1e7;  // k0 [N/m]: an on-site frequency of 8.36 kHz for the paper's beads
constexpr std::size_t cradle_beads = 21, cradle_centre = 10;

BreatherBranchConfig cradle_config(double offset) {
  BreatherBranchConfig c;
  c.chain.source =
      Quasiperiodic{.kind = Quasiperiodic::Kind::s1, .modulation = 0, .phase = 0, .k0_n_per_m = cradle_spring};
  c.chain.N = cradle_beads;
  c.chain.F0 = 0;
  c.start_offset = offset;
  c.max_points = 1;
  c.shooting.steps_per_period = 1024;
  return c;
}

// The small-amplitude limit. With u_n ≈ a_n cos ω t, harmonic balance at the fundamental (a
// one-sided Hertz contact A [d cos]_+^{3/2} has first Fourier coefficient c A |d|^{1/2} d,
// c = Γ(7/4)/(√π Γ(9/4))) turns the equations of motion into
//   (k − m ω²) a_n = c A [φ(a_{n−1} − a_n) − φ(a_n − a_{n+1})],  φ(d) = |d|^{1/2} d,
// whose solutions scale: a_n = α s_n with s_0 = 1 and m ω² − k = Λ c A α^{1/2}, where (s, Λ) solve
// the stationary discrete p-Schrödinger equation −Λ s_n = φ(s_{n−1} − s_n) − φ(s_n − s_{n+1})
// (p = 5/2). Solved here for the profile symmetric about n = 0 (Λ = 2 φ(1 − s_1) from n = 0), by
// Newton's method with a finite-difference Jacobian, on sites 1 … 8 (s_9 = 0).
struct CradleProfile {
  std::array<double, 9> s{};  // s_0 … s_8
  double lambda = 0;
};

CradleProfile cradle_p_schrodinger() {
  constexpr std::size_t m = 8;
  const auto phi = [](double d) { return std::sqrt(std::abs(d)) * d; };
  const auto equations = [&](const std::array<double, m>& x) {
    std::array<double, m> f{};
    const double lambda = 2 * phi(1 - x[0]);
    for (std::size_t n = 0; n < m; ++n) {
      const double left = n == 0 ? 1.0 : x[n - 1], right = n + 1 < m ? x[n + 1] : 0.0;
      f[n] = lambda * x[n] + phi(left - x[n]) - phi(x[n] - right);
    }
    return f;
  };
  std::array<double, m> x{-0.5, 0.1};  // staggered, away from the solution
  for (int iteration = 0; iteration < 100; ++iteration) {
    const auto f = equations(x);
    double size = 0;
    for (double v : f) size = std::max(size, std::abs(v));
    if (size < 1e-14) break;
    // Jacobian by central differences, then Gaussian elimination with partial pivoting.
    std::array<std::array<double, m + 1>, m> a{};
    for (std::size_t j = 0; j < m; ++j) {
      auto up = x, down = x;
      const double h = 1e-7;
      up[j] += h;
      down[j] -= h;
      const auto fu = equations(up), fd = equations(down);
      for (std::size_t i = 0; i < m; ++i) a[i][j] = (fu[i] - fd[i]) / (2 * h);
    }
    for (std::size_t i = 0; i < m; ++i) a[i][m] = -f[i];
    for (std::size_t k = 0; k < m; ++k) {
      std::size_t pivot = k;
      for (std::size_t i = k + 1; i < m; ++i)
        if (std::abs(a[i][k]) > std::abs(a[pivot][k])) pivot = i;
      std::swap(a[k], a[pivot]);
      for (std::size_t i = k + 1; i < m; ++i) {
        const double r = a[i][k] / a[k][k];
        for (std::size_t j = k; j <= m; ++j) a[i][j] -= r * a[k][j];
      }
    }
    std::array<double, m> dx{};
    for (std::size_t k = m; k-- > 0;) {
      double v = a[k][m];
      for (std::size_t j = k + 1; j < m; ++j) v -= a[k][j] * dx[j];
      dx[k] = v / a[k][k];
    }
    for (std::size_t i = 0; i < m; ++i) x[i] += dx[i];
  }
  CradleProfile out;
  out.s[0] = 1;
  std::copy(x.begin(), x.end(), out.s.begin() + 1);
  out.lambda = 2 * phi(1 - x[0]);
  return out;
}

TEST(BreatherCradle, PSchrodingerProfileIsStaggeredAndSolved) {
  const CradleProfile ps = cradle_p_schrodinger();
  std::printf("p-Schrodinger breather: Lambda = %.10f, s = %.6f %.6f %.6f %.6f %.3e\n", ps.lambda, ps.s[1], ps.s[2],
              ps.s[3], ps.s[4], ps.s[5]);
  EXPECT_GT(ps.lambda, 2);  // above the single bead between rigid neighbours (Λ = 2)
  for (std::size_t n = 1; n < 6; ++n) EXPECT_LT(ps.s[n] * ps.s[n - 1], 0) << n;  // staggered
  for (std::size_t n = 2; n < 6; ++n) EXPECT_LT(std::abs(ps.s[n]), 0.5 * std::abs(ps.s[n - 1])) << n;
}

// At small amplitude the breather tends to the p-Schrödinger breather: (m ω_b² − k)/(c A x0_c^{1/2})
// → Λ and x0/x0_c → s, the deviations shrinking with the frequency offset.
TEST(BreatherCradle, SmallAmplitudeLimitIsThePSchrodingerBreather) {
  const CradleProfile ps = cradle_p_schrodinger();
  const double c = std::tgamma(1.75) / (std::sqrt(std::numbers::pi) * std::tgamma(2.25));
  std::vector<double> lambda_error, profile_error;
  for (double offset : {4e-3, 1e-3, 2.5e-4}) {
    const auto config = cradle_config(offset);
    const Chain chain = config.chain.chain(0);
    const auto branch = continue_breather(config);
    ASSERT_EQ(branch.points.size(), 1u);
    const auto& p = branch.points.front();
    EXPECT_EQ(p.centre, cradle_centre);
    const double k = chain.onsite[cradle_centre], m = chain.mass[cradle_centre], a = chain.contact[cradle_centre];
    EXPECT_EQ(chain.contact[cradle_centre + 1], a);
    const double lambda = (m * p.omega * p.omega - k) / (c * a * std::sqrt(p.x0[cradle_centre]));
    double worst = 0;
    for (std::size_t n = 0; n < cradle_beads; ++n) {
      const std::size_t d = n > cradle_centre ? n - cradle_centre : cradle_centre - n;
      const double expected = d < ps.s.size() ? ps.s[d] : 0.0;
      worst = std::max(worst, std::abs(p.x0[n] / p.x0[cradle_centre] - expected));
    }
    lambda_error.push_back(std::abs(lambda / ps.lambda - 1));
    profile_error.push_back(worst);
    std::printf("offset %.2e: amplitude %.3e m, Lambda %.8f (relative error %.2e), profile error %.2e, Newton %d\n",
                offset, p.x0[cradle_centre], lambda, lambda_error.back(), worst, p.iterations);
  }
  // The next order is O(ε), ε ∝ the offset: the errors fall about fourfold per step.
  for (std::size_t i = 1; i < lambda_error.size(); ++i) {
    EXPECT_LT(lambda_error[i], lambda_error[i - 1] / 2.5);
    EXPECT_LT(profile_error[i], profile_error[i - 1] / 2.5);
  }
  EXPECT_LT(lambda_error.back(), 1e-2);
  EXPECT_LT(profile_error.back(), 1e-2);
}

// A breather well off the small-amplitude limit: periodic under direct integration, its
// multipliers in symplectic pairs; the branch from it goes up in frequency (hardening) with the
// amplitude and energy growing.
TEST(BreatherCradle, BreatherIsPeriodicAndHardens) {
  auto config = cradle_config(1e-2);
  config.max_points = 6;
  config.shooting.tolerance = 1e-12;  // so that one period of direct integration can check 1e-10
  const Chain chain = config.chain.chain(0);
  const auto branch = continue_breather(config);
  ASSERT_EQ(branch.points.size(), 6u) << branch.stop_reason;
  const double onsite_khz = std::sqrt(cradle_spring / chain.mass[cradle_centre]) / (2 * std::numbers::pi) / 1e3;
  EXPECT_NEAR(branch.seed_khz, onsite_khz, 1e-12 * onsite_khz);
  EXPECT_EQ(branch.seed_site, static_cast<long>(cradle_centre + 1));
  EXPECT_NE(branch.verdict_untrusted_reason.find("does not converge with the steps per period"), std::string::npos);
  double f = onsite_khz, amplitude = 0, energy = 0;
  for (const auto& p : branch.points) {
    EXPECT_GT(p.freq_khz, f);
    EXPECT_GT(p.amplitude, amplitude);
    EXPECT_GT(p.energy, energy);
    EXPECT_EQ(p.centre, cradle_centre);
    f = p.freq_khz, amplitude = p.amplitude, energy = p.energy;
    EXPECT_LT(p.floquet.reciprocal_error, 1e-8);
    EXPECT_LT(p.floquet.product_error, 1e-8);
    EXPECT_FALSE(p.verdict_trusted);  // F0 = 0: the map's verdict (Long_BreatherCradle below)
    std::printf("%.6f kHz: amplitude %.3e m, max|mu| %.10f, +1 pair split %.2e, residual %.1e, open %.3f\n", p.freq_khz,
                p.amplitude, p.floquet.max_modulus, p.floquet.unit_pair_distance, p.residual, p.max_open_fraction);
  }
  const auto& p = branch.points.front();
  const double one = fixtures::state_error_after(chain, p, 1024, 1);
  EXPECT_LT(one, 1e-10);
  std::printf("after 1 period: relative state error %.2e\n", one);
  if (p.floquet.stable) {
    const double many = fixtures::state_error_after(chain, p, 1024, 1000);
    std::printf("after 1000 periods: relative state error %.2e\n", many);
    EXPECT_LT(many, 1e-6);
  }
}

// Going up (these breathers harden) to 8.0 kHz, which comes back from kHz → rad/s → kHz as
// 7.999999999999999: the branch ends at exactly 8.0 after a few steps, each point above the last
// (it once computed the target twice and divided its secant by zero). The on-site frequency is
// put 0.4 % below the target by k0 (f ∝ k0^{1/2}).
TEST(BreatherCradle, BranchEndsExactlyAtTargetGoingUp) {
  const double target = 8.0;
  auto c = cradle_config(1e-3);
  const Chain chain = c.chain.chain(0);
  const double onsite_khz =
      std::sqrt(chain.onsite[cradle_centre] * chain.inverse_mass[cradle_centre]) / (2e3 * std::numbers::pi);
  c.chain.as<Quasiperiodic>()->k0_n_per_m = cradle_spring * std::pow(target / 1.004 / onsite_khz, 2);
  c.target_khz = target;
  c.max_points = 20;
  const auto branch = continue_breather(c);
  ASSERT_EQ(branch.stop_reason, "target frequency reached");
  EXPECT_LT(branch.points.size(), c.max_points);
  EXPECT_EQ(branch.points.back().freq_khz, target);
  for (std::size_t k = 1; k < branch.points.size(); ++k)
    EXPECT_GT(branch.points[k].freq_khz, branch.points[k - 1].freq_khz) << "point " << k;
}

// How a perturbed orbit leaves a breather under direct integration (SABA2C, `steps` per period,
// `periods` periods): the distance of (u, u̇/ω_b) from the orbit's closed curve (the least over its
// `steps` states of one period), relative to ‖x0‖, after each period. A distance from the curve,
// not from the state at the same time: a perturbation along the family (another amplitude, so
// another frequency) drifts in phase, linearly in time (the +1 Jordan block), but stays as close
// to the curve as it started, while an unstable multiplier μ makes it grow as |μ| per period.
struct CradleDeparture {
  std::vector<double> distance;  // after period 1 … periods
  // exp of the least-squares slope of ln distance over the second half of the periods: the growth
  // per period (1: none)
  double growth = 0;
};

CradleDeparture cradle_departure(const Chain& chain, const BreatherPoint& p, std::size_t steps, std::size_t periods,
                                 double kick) {
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const std::size_t n = chain.size();
  const double tau = 2 * std::numbers::pi / p.omega / static_cast<double>(steps);
  State start(n);
  start.u = p.x0;
  std::vector<double> curve;  // steps × 2n: (u, u̇/ω_b) along one period
  curve.reserve(steps * 2 * n);
  auto reference = make_splitting_propagator(law, chain, saba2c(), tau, start, {.enabled = false});
  for (std::size_t k = 0; k < steps; ++k) {
    for (std::size_t i = 0; i < n; ++i) curve.push_back(reference->displacement()[i]);
    for (std::size_t i = 0; i < n; ++i) curve.push_back(reference->velocity()[i] / p.omega);
    reference->advance(1);
  }
  double norm = 0;
  for (double x : p.x0) norm += x * x;
  for (std::size_t i = 0; i < n; ++i) start.u[i] += kick * p.amplitude * std::sin(0.7 * static_cast<double>(i) + 0.3);
  auto perturbed = make_splitting_propagator(law, chain, saba2c(), tau, start, {.enabled = false});
  CradleDeparture out;
  std::vector<double> now(2 * n);
  for (std::size_t period = 0; period < periods; ++period) {
    perturbed->advance(steps);
    for (std::size_t i = 0; i < n; ++i) {
      now[i] = perturbed->displacement()[i];
      now[n + i] = perturbed->velocity()[i] / p.omega;
    }
    double least = 1e300;
    for (std::size_t k = 0; k < steps; ++k) {
      double d = 0;
      for (std::size_t j = 0; j < 2 * n; ++j) d += std::pow(now[j] - curve[k * 2 * n + j], 2);
      least = std::min(least, d);
    }
    out.distance.push_back(std::sqrt(least / norm));
  }
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
  for (std::size_t k = periods / 2; k < periods; ++k) {
    const double x = static_cast<double>(k + 1), y = std::log(out.distance[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++m;
  }
  out.growth = std::exp((m * sxy - sx * sy) / (m * sxx - sx * sx));
  return out;
}

// The branch's HDF5 file says what its CSV and JSON say: every F0 = 0 verdict untrusted (dataset
// verdict_trusted all 0), with the branch's reason as the attribute verdict_untrusted_reason.
TEST(BreatherCradle, Hdf5FileMarksEveryVerdictUntrusted) {
  auto config = cradle_config(1e-2);
  config.max_points = 3;
  const auto branch = continue_breather(config);
  ASSERT_EQ(branch.points.size(), 3u) << branch.stop_reason;
  ASSERT_FALSE(branch.verdict_untrusted_reason.empty());
  const std::string path = testing::scratch_path("breather_cradle_test", "cradle.h5");
  write_breather_hdf5(path, branch)->commit();
  const fixtures::Hdf5Verdicts verdicts = fixtures::read_hdf5_verdicts(path);
  ASSERT_TRUE(verdicts.ok);
  EXPECT_EQ(verdicts.trusted, (std::vector<std::uint64_t>{0, 0, 0}));
  EXPECT_EQ(verdicts.reason, branch.verdict_untrusted_reason);
  EXPECT_NE(verdicts.reason.find("F0 = 0"), std::string::npos);
}

// Issue 42, item 5: is the F0 = 0 branch's "real" instability (max|μ| 1.0074 at 128 steps per
// period) a property of the orbit or of the discretization? The most unstable point of the tool's
// default branch (128 steps per period, as `breathers --quasi s1 --modulation 0 --phase 0
// --k0-n-per-m 1e7 --F0 0 --N 21 --max-points 30`) is recomputed at 256 … 8192 steps per period
// with SABA2C and with ABA864 (no corrector; Newton from its profile at its frequency, to 1e-12)
// and its multipliers taken there; a perturbation of 1e-9 is integrated 2000 periods at 128 steps
// and 20000 at 1024 and 4096. Measured (docs/breathers.md): each map's multiplier is real — the
// perturbation grows by max|μ| per period to 4 digits (1.0073678 at 128 steps, 1.0003716 against
// 1.0003719 at 4096) — but the verdict does not converge with the step count (stable at 256,
// 2048, 8192 for both schemes; max|μ| − 1 up to 8.3e-4 in between), so it says nothing about the
// orbit of the equations of motion: the F0 = 0 verdicts stay untrusted (verdict_trusted false).
// Fails if the verdicts ever converge (then the rule and the docs are to be revisited).
TEST(Long_BreatherCradle, ClaimedInstabilityIsEachMapsButDoesNotConverge) {
  auto branch_config = cradle_config(1e-3);
  branch_config.max_points = 30;
  branch_config.shooting.steps_per_period = 128;
  const Chain chain = branch_config.chain.chain(0);
  const auto branch = continue_breather(branch_config);
  const BreatherPoint* worst = &branch.points.front();
  for (const auto& p : branch.points)
    if (p.floquet.max_modulus > worst->floquet.max_modulus) worst = &p;
  ASSERT_GT(worst->floquet.max_modulus, 1.005);
  EXPECT_FALSE(worst->verdict_trusted);
  std::printf("128 steps: most unstable point %.6f kHz, max|mu| %.7f (%s)\n", worst->freq_khz,
              worst->floquet.max_modulus, worst->floquet.instability.c_str());
  const auto recomputed = [&](std::size_t steps, const SplittingScheme& scheme) {
    BreatherBranchConfig c = cradle_config(1e-3);
    c.seed_profile = worst->x0;
    c.start_khz = worst->freq_khz;
    c.shooting.steps_per_period = steps;
    c.shooting.tolerance = 1e-12;
    c.shooting.scheme = scheme;
    return continue_breather(c).points.front();
  };
  // Each map's multiplier is what a perturbation does under that map.
  for (const auto& [steps, periods] :
       std::vector<std::pair<std::size_t, std::size_t>>{{128, 2000}, {1024, 20000}, {4096, 20000}}) {
    const BreatherPoint p = recomputed(steps, saba2c());
    const CradleDeparture d = cradle_departure(chain, p, steps, periods, 1e-9);
    std::printf(
        "SABA2C %4zu steps: max|mu| %.7f (%s); distance after 1, %zu, %zu periods %.2e %.2e %.2e; growth "
        "per period %.7f\n",
        steps, p.floquet.max_modulus, p.floquet.instability.c_str(), periods / 2, periods, d.distance[0],
        d.distance[periods / 2 - 1], d.distance[periods - 1], d.growth);
    if (p.floquet.stable) EXPECT_LT(d.growth - 1, 1e-4) << steps;  // no exponential departure (measured 4.9e-5 at 1024)
    else EXPECT_NEAR(d.growth, p.floquet.max_modulus, 1e-4 * (p.floquet.max_modulus - 1) + 2e-6) << steps;
  }
  // The verdicts at 256 … 8192 steps: both kinds, for both schemes, and small.
  for (const auto& scheme : {saba2c(), aba864()}) {
    int stable = 0, unstable = 0;
    for (std::size_t steps = 256; steps <= 8192; steps *= 2) {
      const BreatherPoint p = recomputed(steps, scheme);
      std::printf("%s %4zu steps: max|mu| %.8f (%s)\n", scheme.name.c_str(), steps, p.floquet.max_modulus,
                  p.floquet.instability.c_str());
      (p.floquet.stable ? stable : unstable) += 1;
      EXPECT_LT(p.floquet.max_modulus, 1 + 1e-3) << scheme.name << ' ' << steps;
    }
    EXPECT_GT(stable, 0) << scheme.name;
    EXPECT_GT(unstable, 0) << scheme.name;
  }
}

TEST(BreatherCradle, ZeroPrecompressionNeedsOnsiteSprings) {
  const auto parameter_of = [](const BreatherBranchConfig& c) {
    try {
      continue_breather(c);
    } catch (const InvalidInput& e) {
      return e.parameter();
    }
    return std::string("no exception");
  };
  BreatherBranchConfig bare;
  bare.chain.N = 21;
  bare.chain.F0 = 0;
  bare.site = 11;
  EXPECT_EQ(parameter_of(bare), "F0");  // no springs: no breathers
  auto c = cradle_config(1e-2);
  c.mode = 3;
  EXPECT_EQ(parameter_of(c), "mode");
  c.mode = 0;
  c.site = 22;
  EXPECT_EQ(parameter_of(c), "site");
  c.site = 0;
  c.law = ForceLawKind::fpu;
  EXPECT_EQ(parameter_of(c), "law");
  c.law = ForceLawKind::hertz;
  c.start_offset = BreatherBranchConfig{}.start_offset;  // an offset with start_khz is refused: it takes no effect
  c.start_khz = 1;                                       // below the on-site frequency: these breathers lie above it
  EXPECT_EQ(parameter_of(c), "start_khz");
  auto pressed = cradle_config(1e-2);
  pressed.chain.F0 = 10;
  pressed.site = 3;
  EXPECT_EQ(parameter_of(pressed), "site");
}

}  // namespace
}  // namespace granular
