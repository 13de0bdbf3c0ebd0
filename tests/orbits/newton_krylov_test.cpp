// Newton–Krylov shooting (orbits/periodic_orbit.hpp, ShootingConfig::newton = krylov) against
// dense Newton on the same problem: the same orbit to the tolerance, superlinear convergence, and
// the preconditioner's effect on the GMRES iterations; and a breather of N = 1001 beads (above the
// dense limit) with its ARPACK multipliers.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "granular/detail/euclidean_norm.hpp"
#include "granular/error.hpp"
#include "granular/linear/band_edges.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/orbits/breather_branch.hpp"
#include "granular/orbits/detail/shooting_krylov.hpp"
#include "granular/orbits/floquet.hpp"
#include "granular/orbits/periodic_orbit.hpp"

namespace granular {
namespace {

using detail::euclidean_norm;

// `n` beads alternating from `centre_type` (the centre bead is of that type), ξ = 0.5, seeded from
// the optical band's lowest mode: the gap breathers of the 41-bead tests in a longer chain.
BreatherBranchConfig diatomic_config(std::size_t n, int centre_type) {
  const BandEdges edges = band_edges(steel, paper_r1, 0.5, 10);
  BreatherBranchConfig c;
  Configuration types(n);
  const std::size_t centre = n / 2;
  for (std::size_t i = 0; i < n; ++i)
    types[i] = static_cast<std::uint8_t>((i + centre) % 2 == 0 ? centre_type : 3 - centre_type);
  c.chain.source = GivenTypes{.types = types, .xi = 0.5};
  const Spectrum s = spectrum(dynamical_matrix(c.chain.chain(0)));
  long k = 0;
  while (s.freq_khz[static_cast<std::size_t>(k)] < (edges.fb1 + edges.fb2) / 2e3) ++k;
  c.mode = k + 1;
  return c;
}

void print_history(const char* what, const PeriodicOrbit& o) {
  std::printf("%s: residuals", what);
  for (double r : o.residuals) std::printf(" %.2e", r);
  if (!o.krylov_iterations.empty()) {
    std::printf("; GMRES iterations");
    for (int k : o.krylov_iterations) std::printf(" %d", k);
  }
  std::printf("\n");
}

/// The sixth point of the light-centred gap-breather branch of 201 beads (6 points into the gap:
/// the contacts closed, the profile well nonlinear), its profile distorted by 1 %.
struct DistortedBreather {
  BreatherBranch branch;
  Chain chain;
  std::vector<double> guess;
};

const DistortedBreather& distorted_breather() {
  static const DistortedBreather d = [] {
    auto c = diatomic_config(201, 2);
    c.max_points = 6;
    DistortedBreather d{continue_breather(c), c.chain.chain(0), {}};
    if (d.branch.points.size() == 6) d.guess = d.branch.points.back().x0;  // else empty: the tests say why
    for (std::size_t i = 0; i < d.guess.size(); ++i) d.guess[i] *= 1 + 0.01 * std::cos(0.9 * static_cast<double>(i));
    return d;
  }();
  return d;
}

// Dense and matrix-free Newton at the branch's step count, both to 1e-13 (near the rounding
// floor): J is ill-conditioned here (2 ω_b lies in the optical band), so two solutions at 1e-10
// differ by ~1e-8 along its near-null directions.
std::pair<ShootingConfig, ShootingConfig> dense_and_krylov(const DistortedBreather& d) {
  ShootingConfig dense{.steps_per_period = d.branch.steps_per_period, .tolerance = 1e-13, .newton = NewtonMethod::dense};
  ShootingConfig krylov = dense;
  krylov.newton = NewtonMethod::krylov;
  return {dense, krylov};
}

/// |x0 of `krylov` − x0 of `dense`| / |x0 of `dense`|: how far the two solutions' turning states lie apart.
double x0_relative_gap(const PeriodicOrbit& krylov, const PeriodicOrbit& dense) {
  std::vector<double> gap(dense.x0.size());
  for (std::size_t i = 0; i < gap.size(); ++i) gap[i] = krylov.x0[i] - dense.x0[i];
  return euclidean_norm(gap) / euclidean_norm(dense.x0);
}

// From a 1 % distortion of a light-centred gap breather of 201 beads (6 points into the gap: the
// contacts closed, the profile well nonlinear), Newton–Krylov lands on the orbit dense Newton
// finds, converging superlinearly in few GMRES iterations per step.
TEST(NewtonKrylov, SameOrbitAsDenseNewtonAt201Beads) {
  const DistortedBreather& d = distorted_breather();
  ASSERT_FALSE(d.guess.empty()) << d.branch.stop_reason;
  const ForceLaw law = make_force_law(ForceLawKind::hertz, d.chain);
  const auto [dense_config, krylov_config] = dense_and_krylov(d);
  const auto dense = find_periodic_orbit(law, d.chain, d.branch.points.back().omega, d.guess, dense_config);
  const auto krylov = find_periodic_orbit(law, d.chain, d.branch.points.back().omega, d.guess, krylov_config);
  print_history("dense Newton", dense);
  print_history("Newton-Krylov", krylov);
  EXPECT_EQ(dense.newton, "dense");
  EXPECT_EQ(krylov.newton, "krylov");
  const double difference = x0_relative_gap(krylov, dense);
  std::printf("|x0 krylov - x0 dense| / |x0| = %.2e\n", difference);
  EXPECT_LT(difference, 1e-8);
  // Superlinear: each ratio of successive residuals smaller than the one before (above the floor).
  const auto& r = krylov.residuals;
  ASSERT_GE(r.size(), 3u);
  for (std::size_t k = 0; k + 2 < r.size(); ++k)
    if (r[k + 2] > 1e-13) {
      EXPECT_LT(r[k + 2] / r[k + 1], 0.5 * r[k + 1] / r[k]);
    }
  ASSERT_EQ(krylov.krylov_iterations.size(), static_cast<std::size_t>(krylov.iterations));
  EXPECT_LT(*std::max_element(krylov.krylov_iterations.begin(), krylov.krylov_iterations.end()), 50);
}

// The first Newton correction of that problem by GMRES to 1e-6, with and without the
// preconditioner: without it the eigenvalues of J spread over the band and GMRES needs far more
// iterations (each a tangent integration of T/2).
TEST(NewtonKrylov, PreconditionerCutsTheGmresIterations) {
  const DistortedBreather& d = distorted_breather();
  ASSERT_FALSE(d.guess.empty()) << d.branch.stop_reason;
  const ForceLaw law = make_force_law(ForceLawKind::hertz, d.chain);
  const auto velocity =
      half_period_map(law, d.chain, saba2c(), d.branch.steps_per_period, d.branch.points.back().omega, d.guess, false)
          .velocity;
  const detail::ShootingKrylov with(law, d.chain, saba2c(), d.branch.steps_per_period, d.branch.points.back().omega,
                                    true);
  const detail::ShootingKrylov without(law, d.chain, saba2c(), d.branch.steps_per_period, d.branch.points.back().omega,
                                       false);
  const auto a = with.solve(d.guess, velocity, 1e-6, 400);
  const auto b = without.solve(d.guess, velocity, 1e-6, 400);
  std::printf("GMRES to 1e-6 at N = 201: %d iterations preconditioned (residual %.1e), %d without (residual %.1e)\n",
              a.iterations, a.residual, b.iterations, b.residual);
  EXPECT_LE(a.residual, 1e-6);
  EXPECT_LT(5 * a.iterations, b.iterations);
}

// The pseudo-arclength prediction continue_breather makes from two points: one secant length on
// along the unit secant, in units of the last point's ‖x0‖ and ω_b.
ArcPrediction secant_prediction(const std::vector<double>& x_prev, double w_prev, const std::vector<double>& x_last,
                                double w_last) {
  ArcPrediction p;
  p.x_scale = euclidean_norm(x_last);
  p.omega_scale = w_last;
  p.tangent_x.resize(x_last.size());
  for (std::size_t i = 0; i < x_last.size(); ++i) p.tangent_x[i] = (x_last[i] - x_prev[i]) / p.x_scale;
  p.tangent_omega = (w_last - w_prev) / w_last;
  const double length = std::hypot(euclidean_norm(p.tangent_x), p.tangent_omega);
  for (double& t : p.tangent_x) t /= length;
  p.tangent_omega /= length;
  p.x.resize(x_last.size());
  for (std::size_t i = 0; i < x_last.size(); ++i) p.x[i] = x_last[i] + length * p.tangent_x[i] * p.x_scale;
  p.omega = w_last * (1 + length * p.tangent_omega);
  return p;
}

// The matrix-free bordered corrector against the dense one: from the same predictions along the
// 201-bead branch (each from two consecutive points), both land on the same point of the branch.
TEST(NewtonKrylov, BorderedArclengthCorrectorMatchesTheDenseOne) {
  const DistortedBreather& d = distorted_breather();
  ASSERT_FALSE(d.guess.empty()) << d.branch.stop_reason;
  const ForceLaw law = make_force_law(ForceLawKind::hertz, d.chain);
  const auto [dense_config, krylov_config] = dense_and_krylov(d);
  const auto& points = d.branch.points;
  for (std::size_t i = 2; i < points.size(); ++i) {
    const auto p = secant_prediction(points[i - 2].x0, points[i - 2].omega, points[i - 1].x0, points[i - 1].omega);
    const auto dense = find_periodic_orbit_on_arc(law, d.chain, p, dense_config);
    const auto krylov = find_periodic_orbit_on_arc(law, d.chain, p, krylov_config);
    EXPECT_EQ(dense.newton, "dense");
    EXPECT_EQ(krylov.newton, "krylov");
    const double difference = x0_relative_gap(krylov, dense);
    std::printf("arc point %zu: %.9f kHz, omega differs by %.1e, x0 by %.1e; ", i,
                dense.omega / 2e3 / 3.141592653589793, krylov.omega / dense.omega - 1, difference);
    print_history("Newton-Krylov", krylov);
    EXPECT_NEAR(krylov.omega / dense.omega, 1.0, 1e-12);
    EXPECT_LT(difference, 1e-8);
    ASSERT_EQ(krylov.krylov_iterations.size(), static_cast<std::size_t>(krylov.iterations));
    EXPECT_LT(*std::max_element(krylov.krylov_iterations.begin(), krylov.krylov_iterations.end()), 50);
  }
}

// Above the dense limit (N = 1001): the light-centred gap breather of 101 beads at 33.1 kHz (0.7 kHz
// into the gap, localized, contacts closed) in the middle of a 1001-bead chain of the same pattern
// (zeros around it), Newton–Krylov at its frequency and 1e-3 below, then three matrix-free
// arclength steps from the secant: every point periodic to 1e-10, further down into the gap
// (label long: 28 s on the loaded 2-core VM, its 101-bead branch included).
TEST(Long_NewtonKrylov, ArclengthAbove1000BeadsIsMatrixFree) {
  auto small = diatomic_config(101, 2);
  small.target_khz = 33.1;
  small.max_points = 40;
  const auto branch = continue_breather(small);
  ASSERT_EQ(branch.points.back().freq_khz, 33.1) << branch.stop_reason;
  const auto c = diatomic_config(1001, 2);
  const Chain chain = c.chain.chain(0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  std::vector<double> seed(1001, 0.0);
  std::copy(branch.points.back().x0.begin(), branch.points.back().x0.end(), seed.begin() + 450);
  const ShootingConfig config{.steps_per_period = branch.steps_per_period};  // automatic: Krylov above 1000
  const ShootingConfig dense{.steps_per_period = branch.steps_per_period, .newton = NewtonMethod::dense};
  const auto nowhere = secant_prediction(seed, 1.001, seed, 1.0);
  EXPECT_THROW(find_periodic_orbit_on_arc(law, chain, nowhere, dense), InvalidInput);  // dense refused above 1000
  const double w = branch.points.back().omega;
  auto previous = find_periodic_orbit(law, chain, w, seed, config);
  auto last = find_periodic_orbit(law, chain, w * (1 - 1e-3), previous.x0, config);
  for (int k = 0; k < 3; ++k) {
    const auto p = secant_prediction(previous.x0, previous.omega, last.x0, last.omega);
    auto next = find_periodic_orbit_on_arc(law, chain, p, config);
    std::printf("N = 1001 arc step %d: %.9f kHz; ", k, next.omega / 2e3 / 3.141592653589793);
    print_history("Newton-Krylov", next);
    EXPECT_EQ(next.newton, "krylov");
    EXPECT_LT(next.omega, last.omega);
    previous = std::move(last);
    last = std::move(next);
  }
}

TEST(NewtonKrylov, AutomaticChoiceAndBadInput) {
  EXPECT_FALSE(uses_newton_krylov(1000, {}));
  EXPECT_TRUE(uses_newton_krylov(1001, {}));
  EXPECT_TRUE(uses_newton_krylov(10, {.newton = NewtonMethod::krylov}));
  try {
    uses_newton_krylov(1001, {.newton = NewtonMethod::dense});
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "N");
  }
  EXPECT_EQ(parse_newton_method("krylov"), NewtonMethod::krylov);
  EXPECT_EQ(to_string(NewtonMethod::automatic), "auto");
  EXPECT_THROW(parse_newton_method("gmres"), InvalidInput);
}

// N = 1001, above the dense limit: the most unstable closed-contact heavy-centred gap breather of
// the 101-bead chain, put in the middle of the 1001-bead chain of the same pattern (zeros around
// it), is Newton's seed at its frequency; Newton–Krylov is chosen automatically, ARPACK asked for
// (automatic gives it the dense method's cost, within which these 16 multipliers do not converge,
// and then computes them densely), and ARPACK's largest multiplier is dgeev's on the whole
// 2002 × 2002 monodromy of that orbit.
TEST(Long_NewtonKrylov, GapBreatherOf1001Beads) {
  auto small = diatomic_config(101, 1);
  small.max_points = 60;
  const auto branch = continue_breather(small);
  const BreatherPoint* worst = nullptr;
  for (const auto& q : branch.points)
    if (q.max_open_fraction == 0 && (!worst || q.floquet.max_modulus > worst->floquet.max_modulus)) worst = &q;
  ASSERT_NE(worst, nullptr);
  ASSERT_GT(worst->floquet.max_modulus, 1.1);
  auto c = diatomic_config(1001, 1);
  c.mode = 0;
  c.seed_profile.assign(1001, 0.0);
  std::copy(worst->x0.begin(), worst->x0.end(), c.seed_profile.begin() + 450);
  c.start_khz = worst->freq_khz;
  c.shooting.steps_per_period = branch.steps_per_period;
  c.max_points = 1;
  c.floquet_method = FloquetMethod::arpack;
  const auto large = continue_breather(c);
  const auto& p = large.points.front();
  std::printf("N = 1001 at %.6f kHz: Newton residuals", p.freq_khz);
  for (double r : p.residuals) std::printf(" %.2e", r);
  std::printf("; GMRES iterations");
  for (int k : p.krylov_iterations) std::printf(" %d", k);
  std::printf("; max|mu| %.10f (N = 101 dense: %.10f; %s, %ld products, %d restarts)\n", p.floquet.max_modulus,
              worst->floquet.max_modulus, p.floquet.method.c_str(), p.floquet.operator_applications, p.floquet.restarts);
  EXPECT_EQ(p.newton, "krylov");
  EXPECT_EQ(p.floquet.method, "arpack");
  EXPECT_FALSE(p.floquet.stable);
  EXPECT_EQ(p.floquet.instability, "real");
  // The independent check: dgeev on the 2002 × 2002 monodromy of the same orbit. (The short
  // chain's multiplier differs by ~1 %: its walls are 50 beads from the centre.)
  const Chain chain = c.chain.chain(0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const auto orbit = find_periodic_orbit(law, chain, p.omega, p.x0,
                                         {.steps_per_period = branch.steps_per_period, .newton = NewtonMethod::krylov});
  EXPECT_EQ(orbit.iterations, 0);
  const FloquetSpectrum dense = floquet_stability(law, chain, orbit, c.stability_tolerance);
  std::printf("N = 1001 dense: max|mu| %.12f, ARPACK %.12f (complete %d)\n", dense.max_modulus, p.floquet.max_modulus,
              p.floquet.complete);
  EXPECT_NEAR(p.floquet.max_modulus, dense.max_modulus, 1e-8);
  EXPECT_EQ(dense.instability, "real");
}

}  // namespace
}  // namespace granular
