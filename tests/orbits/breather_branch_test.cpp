// Breathers by shooting and continuation (docs/breathers.md), checked against what does not come
// from the shooting code: the linear spectrum (the small-amplitude limit), Newton's theory
// (quadratic convergence), the symplectic structure (multiplier pairs), band edges of the diatomic
// chain (docs/physics.md, "Band edges"), and direct integration by the library's propagator.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <hdf5.h>

#include "breather_fixtures.hpp"
#include "granular/detail/euclidean_norm.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/error.hpp"
#include "granular/linear/band_edges.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/orbits/breather_branch.hpp"
#include "granular/orbits/periodic_orbit.hpp"
#include "scratch.hpp"

namespace granular {
namespace {

using detail::euclidean_norm;
constexpr double r1 = paper_r1;

// 21 beads of radius R1 with one bead of radius R1/2 in the middle: a light impurity whose
// linear mode lies above the band, localized on it.
BreatherBranchConfig impurity_config() {
  std::vector<double> radii(21, r1);
  radii[10] = 0.5 * r1;
  BreatherBranchConfig c;
  c.chain.source = GivenRadii{.radii = radii};
  c.chain.F0 = 10;
  c.mode = 21;
  c.max_points = 1;
  c.shooting.steps_per_period = 1024;
  return c;
}

Configuration alternating(std::size_t n, int first) {
  Configuration t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<std::uint8_t>(i % 2 == 0 ? first : 3 - first);
  return t;
}

// The number (1…N) of the lowest mode above the middle of the gap: the optical band's lower edge.
long lowest_optical_mode(const Chain& chain, const BandEdges& edges) {
  const Spectrum s = spectrum(dynamical_matrix(chain));
  long k = 0;
  while (s.freq_khz[static_cast<std::size_t>(k)] < (edges.fb1 + edges.fb2) / 2e3) ++k;
  return k + 1;
}

// The diatomic chain of 41 beads with a bead of type `centre_type` in the middle (ξ = 0.5), seeded
// from the optical band's lowest mode.
BreatherBranchConfig diatomic_gap_config(int centre_type, const BandEdges& edges) {
  BreatherBranchConfig c;
  c.chain.source = GivenTypes{.types = alternating(41, centre_type), .xi = 0.5};
  c.mode = lowest_optical_mode(c.chain.chain(0), edges);
  return c;
}

double profile_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double na = 0, nb = 0, dot = 0, d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) na += a[i] * a[i], nb += b[i] * b[i], dot += a[i] * b[i];
  const double sign = dot < 0 ? -1 : 1;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double x = a[i] / std::sqrt(na) - sign * b[i] / std::sqrt(nb);
    d += x * x;
  }
  return std::sqrt(d);
}

// Breathers of `c` (seeded from mode `k`, 0-based) at relative offsets `first`, first/2, first/4
// below the mode tend to the linear mode: frequency (extrapolated to zero energy) and profile; all
// multipliers on the unit circle.
void expect_linear_limit(BreatherBranchConfig c, std::size_t k, double first) {
  const Chain chain = c.chain.chain(0);
  const DynamicalMatrix d = dynamical_matrix(chain);
  const Spectrum modes = spectrum(d, all_modes(), {.vectors = true});
  std::vector<double> mode(chain.size());
  for (std::size_t i = 0; i < mode.size(); ++i) mode[i] = modes.vector(k)[i] * d.inverse_sqrt_mass[i];
  const double omega_linear = std::sqrt(modes.omega2[k]);

  std::vector<BreatherPoint> points;
  std::size_t steps = 0;
  for (double offset : {first, first / 2, first / 4}) {
    c.start_offset = offset;
    const BreatherBranch branch = continue_breather(c);
    steps = branch.steps_per_period;
    points.push_back(branch.points.front());
  }
  // Softening: below the mode. ω(E) is analytic in the energy E (the frequency of a Hamiltonian
  // oscillator is a smooth function of its action), so the quadratic through the three points,
  // extrapolated to E = 0, gives the linear frequency.
  EXPECT_LT(points[0].omega, omega_linear);
  double omega0 = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    double w = points[i].omega;
    for (std::size_t j = 0; j < 3; ++j)
      if (j != i) w *= -points[j].energy / (points[i].energy - points[j].energy);
    omega0 += w;
  }
  EXPECT_NEAR(omega0 / omega_linear, 1.0, 1e-8);
  std::printf("linear limit: extrapolated omega / linear omega - 1 = %.2e\n", omega0 / omega_linear - 1);
  const auto& p1 = points[0];
  const auto& p2 = points[2];
  // The profile tends to the mode (its distance shrinks like the amplitude, √4 = 2 times here).
  const double d1 = profile_difference(p1.x0, mode), d2 = profile_difference(p2.x0, mode);
  EXPECT_LT(d2, 3e-2);
  EXPECT_NEAR(d1 / d2, 2.0, 0.3);
  // Periodic over a whole period of direct integration (shooting integrated half of it and used
  // the time-reversal symmetry; Newton's own residual cannot fail here: it accepted the points).
  for (const auto& p : points) {
    EXPECT_LT(fixtures::state_error_after(chain, p, steps, 1), 1e-8);
    for (const auto mu : p.floquet.multipliers) EXPECT_NEAR(std::abs(mu), 1.0, 1e-6);
  }
}

TEST(BreatherBranch, LinearLimitIsTheLinearModeAtItsFrequency) { expect_linear_limit(impurity_config(), 20, 4e-4); }

// The same on a quasiperiodic S1 chain above its transition (λ = 0.8: every linear mode localized),
// whose on-site springs enter the shooting map, its tangent map and the linear seed alike.
TEST(BreatherBranch, LinearLimitOnAnOnsiteSpringChain) {
  BreatherBranchConfig c;
  c.chain.source = Quasiperiodic{.kind = Quasiperiodic::Kind::s1, .modulation = 0.8, .phase = 0.4};
  c.chain.N = 101;
  c.chain.F0 = 10;
  c.mode = 101;
  c.max_points = 1;
  expect_linear_limit(c, 100, 4e-5);  // below a quarter of the way to mode 100, 2e-4 lower
}

TEST(BreatherBranch, NewtonConvergesQuadratically) {
  auto c = impurity_config();
  c.start_offset = 2e-2;
  const auto p = continue_breather(c).points.front();
  const Chain chain = c.chain.chain(0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  auto guess = p.x0;  // a 1 % distortion of the breather
  for (std::size_t i = 0; i < guess.size(); ++i) guess[i] *= 1 + 0.01 * std::cos(0.9 * static_cast<double>(i));
  const auto orbit = find_periodic_orbit(law, chain, p.omega, guess, {.steps_per_period = 1024});
  const auto& r = orbit.residuals;
  ASSERT_GE(r.size(), 3u);
  int checked = 0;
  for (std::size_t k = 0; k + 2 < r.size(); ++k) {
    if (r[k + 2] < 1e-13) continue;  // the rounding floor
    const double order = std::log(r[k + 2] / r[k + 1]) / std::log(r[k + 1] / r[k]);
    EXPECT_GT(order, 1.7) << "residuals " << r[k] << ", " << r[k + 1] << ", " << r[k + 2];
    ++checked;
  }
  EXPECT_GE(checked, 1);
  std::printf("Newton residuals:");
  for (double x : r) std::printf(" %.2e", x);
  std::printf("\n");
}

TEST(BreatherBranch, MultipliersComeInSymplecticPairs) {
  auto c = impurity_config();
  c.start_offset = 2e-2;  // nonlinear, contacts closed (with one open the pair splits further, docs/breathers.md)
  const auto p = continue_breather(c).points.front();
  EXPECT_LT(p.floquet.reciprocal_error, 1e-8);
  EXPECT_LT(p.floquet.product_error, 1e-8);
  // The pair at +1 (phase and family) is a Jordan block: an orbit periodic to the residual r
  // splits it by ~√r, not r.
  EXPECT_LT(p.floquet.unit_pair_distance, 30 * std::sqrt(p.residual));
  EXPECT_LT(p.floquet.unit_pair_distance, 1e-7);
  EXPECT_EQ(p.max_open_fraction, 0);
}

// Theocharis et al., PRE 82, 056604 (2010): in a diatomic chain gap breathers bifurcate from the
// lower edge of the optical band into the gap; the family centred on a heavy bead is unstable,
// the one centred on a light bead can be stable.
TEST(BreatherBranch, DiatomicGapBreathersBifurcateFromTheOpticalEdgeIntoTheGap) {
  const BandEdges edges = band_edges(steel, r1, 0.5, 10);
  for (int centre_type : {1, 2}) {
    BreatherBranchConfig c = diatomic_gap_config(centre_type, edges);  // bead 21 (the centre) is of type centre_type
    c.target_khz = (edges.fb1 + edges.fb2) / 2e3;
    c.max_points = 60;
    const auto branch = continue_breather(c);
    const Chain chain = c.chain.chain(0);
    ASSERT_GE(branch.points.size(), 5u) << branch.stop_reason;
    EXPECT_NEAR(branch.seed_khz, edges.fb2 / 1e3, 0.05 * edges.fb2 / 1e3);  // the optical band's lower edge
    double last = branch.seed_khz;
    for (const auto& p : branch.points) {
      EXPECT_LT(p.freq_khz, last);  // softening: down into the gap
      EXPECT_GT(p.freq_khz, edges.fb1 / 1e3);
      // Periodic over a whole period of direct integration (Newton accepted these at 1e-10).
      EXPECT_LT(fixtures::state_error_after(chain, p, branch.steps_per_period, 1), 1e-8) << p.freq_khz << " kHz";
      last = p.freq_khz;
    }
    // The paper's two families, up to the first open contact (where the branch stops):
    // heavy-centred, a symmetric profile (x0 odd about the heavy bead 21) that turns unstable
    // through a real multiplier; light-centred, asymmetric about the light bead 21 and stable.
    const auto& x = branch.points.back().x0;
    bool any_unstable = false;
    for (const auto& p : branch.points) any_unstable = any_unstable || !p.floquet.stable;
    if (centre_type == 1) {
      EXPECT_NEAR(x[19], -x[21], 1e-6 * branch.points.back().amplitude);
      EXPECT_TRUE(any_unstable);
      EXPECT_EQ(branch.points.back().floquet.instability, "real");
    } else {
      EXPECT_GT(std::abs(std::abs(x[19]) - std::abs(x[21])), 0.05 * branch.points.back().amplitude);
      EXPECT_EQ(branch.points.back().centre, 20u);
      EXPECT_FALSE(any_unstable);
    }
  }
}

// Through the contact openings the light-centred gap breathers of the 41-bead diatomic chain turn
// back in frequency (docs/breathers.md): natural-parameter continuation stalls at its fold, 18.206
// kHz. Pseudo-arclength follows a branch round a fold: its frequency has an interior minimum with
// converged points after it, higher in energy; before it, down to 19 kHz, its points are the
// fixed-frequency orbits the natural continuation finds (Newton at the same ω_b from the natural
// branch's profile lands on them). Near 18.6 kHz the two continuations part onto different
// branches (both converged orbits), so the natural branch is compared above that only.
// About 8 s: Release pass only.
TEST(Long_BreatherBranch, ArclengthContinuationPassesTheFoldWhereNaturalStops) {
  const BandEdges edges = band_edges(steel, r1, 0.5, 10);
  BreatherBranchConfig c = diatomic_gap_config(2, edges);
  c.through_opening = true;
  c.max_points = 200;
  const BreatherBranch natural = continue_breather(c);
  ASSERT_TRUE(natural.stop_reason.starts_with("Newton failed")) << natural.stop_reason;
  c.continuation = Continuation::arclength;
  c.max_points = 125;
  const BreatherBranch arc = continue_breather(c);
  ASSERT_EQ(arc.points.size(), c.max_points) << arc.stop_reason;
  std::size_t fold = 0;
  for (std::size_t k = 0; k < arc.points.size(); ++k) {
    if (arc.points[k].freq_khz < arc.points[fold].freq_khz) fold = k;
  }
  std::printf("natural stops at %.4f kHz (point %zu); arclength turns at %.4f kHz (point %zu)\n",
              natural.points.back().freq_khz, natural.points.size(), arc.points[fold].freq_khz, fold + 1);
  ASSERT_GT(fold, 0u);
  ASSERT_GE(arc.points.size() - fold, 10u) << "too few points after the fold";
  for (std::size_t k = fold + 1; k < arc.points.size(); ++k) {
    EXPECT_GT(arc.points[k].freq_khz, arc.points[k - 1].freq_khz) << "point " << k;
    EXPECT_GT(arc.points[k].energy, arc.points[k - 1].energy) << "point " << k;
  }
  const Chain chain = c.chain.chain(0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  ShootingConfig shooting = c.shooting;
  shooting.steps_per_period = arc.steps_per_period;
  for (const BreatherPoint& from : natural.points) {
    if (from.freq_khz < 19) break;
    std::size_t near = 0;
    for (std::size_t j = 0; j < fold; ++j)
      if (std::abs(arc.points[j].freq_khz - from.freq_khz) < std::abs(arc.points[near].freq_khz - from.freq_khz))
        near = j;
    const PeriodicOrbit fixed = find_periodic_orbit(law, chain, arc.points[near].omega, from.x0, shooting);
    // Two orbits converged to a relative residual of 1e-10 differ by up to that times the
    // Jacobian's condition (4e-7 next to the band edge, where a linear mode is near ω_b); another
    // branch at the same frequency differs by ~1e-2 (0.09 at 18.2 kHz).
    EXPECT_LT(profile_difference(fixed.x0, arc.points[near].x0), 1e-5) << arc.points[near].freq_khz << " kHz";
    EXPECT_NEAR(euclidean_norm(fixed.x0), euclidean_norm(arc.points[near].x0), 1e-5 * euclidean_norm(fixed.x0));
  }
}

TEST(BreatherBranch, StableBreatherStaysPeriodicUnderDirectIntegration) {
  auto c = impurity_config();
  c.start_offset = 2e-2;
  const auto p = continue_breather(c).points.front();
  ASSERT_TRUE(p.floquet.stable);
  const double err = fixtures::state_error_after(c.chain.chain(0), p, 1024, 1000);
  EXPECT_LT(err, 1e-6);
  std::printf("after 1000 periods: relative state error %.2e\n", err);
}

// A breather of a disordered chain (RDM1, q = 0.5, ξ = 0.5, N = 100, seed 1, realization 0),
// continued from its top linear mode (45.142 kHz, localized near bead 49; docs/breathers.md): the
// stable points stay periodic for 1000 periods of direct integration; the unstable one (max|μ|
// slightly above 1 at the end of the branch) is not asked to.
TEST(BreatherBranch, DisorderedChainBreathersFromAnImpurityModeStayPeriodic) {
  BreatherBranchConfig c;
  c.chain.draw().disorder = Disorder::rdm1;
  c.chain.N = 100;
  c.mode = 100;
  c.max_points = 5;
  const BreatherBranch branch = continue_breather(c);
  ASSERT_EQ(branch.points.size(), 5u);
  const Chain chain = c.chain.chain(0);
  std::printf("%zu SABA2C steps per period\n", branch.steps_per_period);
  std::size_t stable = 0;
  for (const BreatherPoint& p : branch.points) {
    EXPECT_EQ(p.max_open_fraction, 0.0);
    if (!p.floquet.stable) continue;
    ++stable;
    const double err = fixtures::state_error_after(chain, p, branch.steps_per_period, 1000);
    std::printf("%.3f kHz, energy %.3g J: relative state error after 1000 periods %.2e\n", p.freq_khz, p.energy, err);
    EXPECT_LT(err, 1e-6) << p.freq_khz << " kHz";
  }
  EXPECT_GE(stable, 4u);
}

// An unstable breather (heavy-centred diatomic family, contacts closed): a perturbation of 1e-9
// grows by the largest Floquet multiplier per period under direct integration.
TEST(BreatherBranch, UnstableBreatherDepartsAtTheFloquetRate) {
  const BandEdges edges = band_edges(steel, r1, 0.5, 10);
  BreatherBranchConfig c = diatomic_gap_config(1, edges);
  c.max_points = 60;
  const auto branch = continue_breather(c);
  const BreatherPoint* worst = nullptr;  // the most unstable point with every contact closed
  for (const auto& p : branch.points)
    if (p.max_open_fraction == 0 && (!worst || p.floquet.max_modulus > worst->floquet.max_modulus)) worst = &p;
  ASSERT_NE(worst, nullptr);
  ASSERT_GT(worst->floquet.max_modulus, 1.1);
  const Chain chain = c.chain.chain(0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  State start(chain.size());
  start.u = worst->x0;
  for (std::size_t i = 0; i < chain.size(); ++i)
    start.u[i] += 1e-9 * worst->amplitude * std::sin(0.7 * static_cast<double>(i) + 0.3);
  const std::size_t steps = branch.steps_per_period;
  auto prop =
      make_splitting_propagator(law, chain, saba2c(), 2 * std::numbers::pi / worst->omega / static_cast<double>(steps),
                                start, {.enabled = false});
  const auto distance = [&] {
    double d = 0;
    for (std::size_t i = 0; i < chain.size(); ++i)
      d += std::pow(prop->displacement()[i] - worst->x0[i], 2) + std::pow(prop->velocity()[i] / worst->omega, 2);
    return std::sqrt(d);
  };
  prop->advance(10 * steps);  // let the unstable direction dominate
  const double d10 = distance();
  prop->advance(10 * steps);
  const double d20 = distance();
  const double measured = std::pow(d20 / d10, 0.1);
  std::printf("max |mu| %.4f; measured growth per period %.4f\n", worst->floquet.max_modulus, measured);
  EXPECT_NEAR(measured, worst->floquet.max_modulus, 0.02 * worst->floquet.max_modulus);
  EXPECT_LT(d20, 1e-3 * worst->amplitude);  // still linear
}

// Seeded from a state (here a branch point's profile, distorted by 1 %) at its frequency, Newton
// lands on that point, and the branch continues from it.
TEST(BreatherBranch, SeedProfileLandsOnTheOrbitNearIt) {
  auto c = impurity_config();
  c.start_offset = 2e-2;
  c.max_points = 2;
  const BreatherPoint p = continue_breather(c).points.back();
  BreatherBranchConfig from = impurity_config();
  from.mode = 0;
  from.seed_profile = p.x0;
  for (std::size_t i = 0; i < p.x0.size(); ++i)
    from.seed_profile[i] *= 1 + 0.01 * std::sin(1.7 * static_cast<double>(i) + 0.5);
  from.start_khz = p.freq_khz;
  from.max_points = 2;
  const BreatherBranch branch = continue_breather(from);
  ASSERT_EQ(branch.points.size(), 2u) << branch.stop_reason;
  EXPECT_EQ(branch.seed_mode, 0);
  EXPECT_EQ(branch.points[0].freq_khz, p.freq_khz);
  EXPECT_LT(profile_difference(branch.points[0].x0, p.x0), 1e-6);
  EXPECT_NEAR(euclidean_norm(branch.points[0].x0), euclidean_norm(p.x0), 1e-6 * euclidean_norm(p.x0));
  EXPECT_LT(branch.points[1].freq_khz, p.freq_khz);  // on, down the branch
  // What a seed profile needs, named.
  const auto parameter_of = [](const BreatherBranchConfig& bad) {
    try {
      validate(bad);
    } catch (const InvalidInput& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  BreatherBranchConfig bad = from;
  bad.seed_profile.pop_back();
  EXPECT_EQ(parameter_of(bad), "seed_profile");
  bad = from;
  bad.start_khz = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(parameter_of(bad), "start_khz");
  bad = from;
  bad.mode = 3;
  EXPECT_EQ(parameter_of(bad), "seed_profile");
  bad = from;
  bad.seed_profile.assign(bad.seed_profile.size(), 0.0);
  EXPECT_EQ(parameter_of(bad), "seed_profile");
}

// The HDF5 file holds what the branch holds: profiles, multipliers and verdict flags, point by
// point (F0 > 0: every verdict trusted, no reason; F0 = 0 in BreatherCradle.Hdf5FileMarks…).
TEST(BreatherBranch, Hdf5FileHoldsTheProfilesAndMultipliers) {
  auto c = impurity_config();
  c.max_points = 2;
  const BreatherBranch branch = continue_breather(c);
  ASSERT_EQ(branch.points.size(), 2u);
  const std::string path = testing::scratch_path("breather_branch_test", "branch.h5");
  write_breather_hdf5(path, branch)->commit();
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const auto read = [&](const char* name, std::size_t size) {
    std::vector<double> data(size);
    const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
    EXPECT_GE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), 0) << name;
    H5Dclose(set);
    return data;
  };
  const std::size_t n = 21;
  const auto x0 = read("x0", 2 * n), re = read("multipliers_real", 4 * n), im = read("multipliers_imag", 4 * n);
  const auto open = read("open_fraction", 2 * (n + 1)), freq = read("freq_khz", 2);
  H5Fclose(file);
  for (std::size_t j = 0; j < 2; ++j) {
    const BreatherPoint& p = branch.points[j];
    EXPECT_EQ(freq[j], p.freq_khz);
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(x0[j * n + i], p.x0[i]);
    for (std::size_t i = 0; i < 2 * n; ++i) {
      EXPECT_EQ(re[j * 2 * n + i], p.floquet.multipliers[i].real());
      EXPECT_EQ(im[j * 2 * n + i], p.floquet.multipliers[i].imag());
    }
    for (std::size_t k = 0; k <= n; ++k) EXPECT_EQ(open[j * (n + 1) + k], p.open_fraction[k]);
  }
  const fixtures::Hdf5Verdicts verdicts = fixtures::read_hdf5_verdicts(path);
  ASSERT_TRUE(verdicts.ok);
  EXPECT_EQ(verdicts.trusted, (std::vector<std::uint64_t>{1, 1}));
  EXPECT_EQ(verdicts.reason, "");
  EXPECT_TRUE(branch.verdict_untrusted_reason.empty());
}

// A target ends the branch at exactly the frequency asked for. These six come back from
// kHz → rad/s → kHz a rounding off (33.2 as 33.20000000000001, 32.5 as 32.49999999999999):
// compared after that round trip, the branch once ran past them to max_points or computed the
// target twice and divided its secant by zero. The light impurity's mode is put 0.4 % above each
// target by F0 (every frequency of a Hertz chain goes as F0^{1/6}), a few steps down to it.
TEST(BreatherBranch, BranchEndsExactlyAtTargetsThatDoNotRoundTrip) {
  const auto base = impurity_config();
  const double top = spectrum(dynamical_matrix(base.chain.chain(0))).freq_khz.back();
  for (double target : {12.3, 15.0, 25.0, 32.5, 32.8, 33.2}) {
    ASSERT_NE(2 * std::numbers::pi * target * 1e3 / (2 * std::numbers::pi) / 1e3, target);  // the case at issue
    auto c = base;
    c.chain.F0 = base.chain.F0 * std::pow(1.004 * target / top, 6);
    c.target_khz = target;
    c.max_points = 20;
    const auto branch = continue_breather(c);
    ASSERT_EQ(branch.stop_reason, "target frequency reached") << target << " kHz";
    EXPECT_LT(branch.points.size(), c.max_points);
    EXPECT_EQ(branch.points.back().freq_khz, target);
    EXPECT_NEAR(branch.points.back().omega, 2 * std::numbers::pi * target * 1e3, 1e-12 * target * 1e4);
    for (std::size_t k = 1; k < branch.points.size(); ++k)
      EXPECT_LT(branch.points[k].freq_khz, branch.points[k - 1].freq_khz) << target << " kHz, point " << k;
  }
}

// The same by pseudo-arclength, whose steps land where the corrector puts ω_b: the branch still ends
// at exactly the target (a corrected point past it is replaced by the natural step onto it), every
// point between the start and the target. The mode 1.5 % above the target: several arc steps.
TEST(BreatherBranch, ArclengthBranchEndsExactlyAtItsTarget) {
  const auto base = impurity_config();
  const double top = spectrum(dynamical_matrix(base.chain.chain(0))).freq_khz.back();
  for (double target : {32.5, 33.2}) {
    auto c = base;
    c.chain.F0 = base.chain.F0 * std::pow(1.015 * target / top, 6);
    c.target_khz = target;
    c.max_points = 30;
    c.continuation = Continuation::arclength;
    const auto branch = continue_breather(c);
    ASSERT_EQ(branch.stop_reason, "target frequency reached") << target << " kHz";
    EXPECT_GE(branch.points.size(), 4u);  // arclength steps were taken
    EXPECT_EQ(branch.points.back().freq_khz, target);
    for (std::size_t k = 1; k < branch.points.size(); ++k) {
      EXPECT_LT(branch.points[k].freq_khz, branch.points[k - 1].freq_khz) << target << " kHz, point " << k;
      EXPECT_GE(branch.points[k].freq_khz, target) << target << " kHz, point " << k;
    }
  }
}

// Tolerances of zero, below zero or NaN are refused by the library (so alike by the tool and Python).
TEST(BreatherBranch, ToleranceAndStabilityToleranceMustBePositive) {
  for (double bad : {0.0, -1e-10, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    auto c = impurity_config();
    c.shooting.tolerance = bad;
    try {
      validate(c);
      ADD_FAILURE() << "tolerance " << bad << " accepted";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.parameter(), "tolerance");
    }
    c = impurity_config();
    c.stability_tolerance = bad;
    try {
      validate(c);
      ADD_FAILURE() << "stability_tolerance " << bad << " accepted";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.parameter(), "stability_tolerance");
    }
  }
}

TEST(BreatherBranch, BadInputIsRefusedBeforeAnyWork) {
  const BandEdges edges = band_edges(steel, r1, 0.5, 10);
  BreatherBranchConfig c;
  c.chain.source = GivenTypes{.types = alternating(41, 1)};
  c.start_khz = 0.5 * edges.fb1 / 1e3;  // inside the acoustic band, no seed
  try {
    continue_breather(c);
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "start_khz");
  }
  c.start_khz = 1.1 * edges.fb3 / 1e3;  // above every band: allowed, seeded from the top mode
  EXPECT_NO_THROW(validate(c));
  c.shooting.max_dense_beads = 40;
  EXPECT_NO_THROW(validate(c));  // beyond the dense limit: Newton-Krylov
  c.shooting.newton = NewtonMethod::dense;
  try {
    validate(c);
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "N");
  }
}

}  // namespace
}  // namespace granular
