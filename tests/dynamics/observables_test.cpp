// The observables (dynamics/observables.hpp) against values worked out by hand from docs/physics.md, "Nonlinear dynamics"'s
// formulas on 3–5-bead configurations, with the arithmetic written here; and the exact relation
// between m̃2 about the excited site and about the energy centroid.
#include "granular/dynamics/observables.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "dynamics_fixtures.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

// A profile E_n with the kicked bead n0 and its moments worked out by hand.
struct HandProfile {
  std::vector<double> e;
  std::size_t site;
  double centroid, m2_site, m2_centroid, ipr;
};

void expect_hand_values(const HandProfile& p) {
  const EnergySpread s = energy_spread(p.e, p.site);
  EXPECT_DOUBLE_EQ(s.total, 4.0);
  EXPECT_DOUBLE_EQ(s.centroid, p.centroid);
  EXPECT_DOUBLE_EQ(s.m2_site, p.m2_site);
  EXPECT_DOUBLE_EQ(s.m2_centroid, p.m2_centroid);
  EXPECT_DOUBLE_EQ(s.ipr, p.ipr);
  EXPECT_EQ(s.m2(SpreadCentre::site), s.m2_site);
  EXPECT_EQ(s.m2(SpreadCentre::centroid), s.m2_centroid);
}

TEST(EnergySpread, HandValuesOfASymmetricProfile) {
  // E = (0, 1, 2, 1, 0), kicked bead n0 = 2 (0-based). Σ E = 4; n̄ = (1·1 + 2·2 + 3·1)/4 = 2.
  // m̃2 about n0 = about n̄ = (1·1 + 0·2 + 1·1)/4 = 0.5; P⁻¹ = (1 + 4 + 1)/4² = 0.375.
  expect_hand_values({{0, 1, 2, 1, 0}, 2, 2.0, 0.5, 0.5, 0.375});
}

TEST(EnergySpread, HandValuesOfAOneSidedProfile) {
  // E = (0, 0, 1, 3, 0), n0 = 2: the energy has left to the right, as after a velocity kick near
  // F0 = 0. Σ E = 4; n̄ = (2·1 + 3·3)/4 = 2.75.
  // about n0: (0²·1 + 1²·3)/4 = 0.75; about n̄: ((−0.75)²·1 + 0.25²·3)/4 = (0.5625 + 0.1875)/4 = 0.1875;
  // and 0.1875 + (2.75 − 2)² = 0.75. P⁻¹ = (1 + 9)/16 = 0.625.
  expect_hand_values({{0, 0, 1, 3, 0}, 2, 2.75, 0.75, 0.1875, 0.625});
  // about bead 0: (2²·1 + 3²·3)/4
  EXPECT_DOUBLE_EQ(energy_spread(std::vector<double>{0, 0, 1, 3, 0}, 0).m2_site, (4.0 * 1 + 9.0 * 3) / 4);
}

TEST(EnergySpread, ReadingOnlyTheBeadsThatHoldEnergyGivesTheSameBits) {
  // What the observers do with an active window: beads outside [begin, end) hold no energy.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const std::size_t n = 20 + trial % 50, begin = trial % 7, end = n - trial % 5;
    std::vector<double> e(n, 0.0);
    for (std::size_t i = begin; i < end; ++i) e[i] = std::pow(u(rng), 5) * 1e-9;
    const std::size_t site = (begin + end) / 2;
    const EnergySpread whole = energy_spread(e, site), part = energy_spread(e, site, begin, end);
    EXPECT_EQ(part.total, whole.total);
    EXPECT_EQ(part.centroid, whole.centroid);
    EXPECT_EQ(part.m2_site, whole.m2_site);
    EXPECT_EQ(part.m2_centroid, whole.m2_centroid);
    EXPECT_EQ(part.ipr, whole.ipr);
  }
}

TEST(EnergySpread, SiteMomentIsCentroidMomentPlusSquaredOffset) {
  // m̃2_site = m̃2_centroid + (n̄ − n0)² for any profile and any n0 (the parallel-axis theorem);
  // equal for a profile symmetric about n0. The code sums both moments directly.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = 3 + trial % 40;
    std::vector<double> e(n);
    for (double& x : e) x = std::pow(u(rng), 3);
    const std::size_t site = static_cast<std::size_t>(u(rng) * static_cast<double>(n));
    const EnergySpread s = energy_spread(e, site);
    const double offset = s.centroid - static_cast<double>(site);
    EXPECT_NEAR(s.m2_site, s.m2_centroid + offset * offset, 1e-12 * (1 + s.m2_site)) << "trial " << trial;
    std::vector<double> symmetric(2 * n + 1);  // mirror about the middle bead n
    for (std::size_t i = 0; i < n; ++i) symmetric[n - 1 - i] = symmetric[n + 1 + i] = e[i];
    symmetric[n] = u(rng);
    const EnergySpread m = energy_spread(symmetric, n);
    EXPECT_NEAR(m.centroid, static_cast<double>(n), 1e-12 * static_cast<double>(n));
    EXPECT_NEAR(m.m2_site, m.m2_centroid, 1e-12 * (1 + m.m2_site));
  }
  EXPECT_EQ(energy_spread(std::vector<double>(4, 0.0), 1).m2_site, 0.0);  // no energy: all zero
  EXPECT_EQ(parse_spread_centre("centroid"), SpreadCentre::centroid);
  EXPECT_THROW(parse_spread_centre("middle"), InvalidInput);
}

// Three type-1 beads between flat walls. docs/physics.md, "The linear spectrum": A11 = 6.897840e9 (bead–bead), A_wall =
// 9.755019e9 N/m^{3/2}, m1 = 3.626368e-3 kg. Bond k joins bead k−1 and bead k (bond 0 and 3 are
// the walls'); strain x_k = u_{k−1} − u_k.
constexpr double a11 = 6.897840e9, a_wall = 9.755019e9, m1 = 3.626368e-3;

TEST(SiteEnergy, HandValuesInTheSonicVacuum) {
  // F0 = 0: Δ = 0 and φ(x) = (2/5) A [x]_+^{5/2}. u = (0, 1 µm, 0), v = (0, 0.1 m/s, 0):
  // x_0 = 0, x_1 = 0 − 1e-6 (bond 1 open: φ_1 = 0), x_2 = 1e-6 − 0 (φ_2 = 0.4 A11 (1e-6)^{2.5}), x_3 = 0.
  // E_0 = (φ_0 + φ_1)/2 = 0; E_1 = m1 0.1²/2 + (φ_1 + φ_2)/2; E_2 = (φ_2 + φ_3)/2.
  const Chain chain = fixtures::homogeneous(3, 0.0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  State s(3);
  s.u = {0, 1e-6, 0};
  s.v = {0, 0.1, 0};
  const double phi2 = 0.4 * a11 * std::pow(1e-6, 2.5);
  const std::vector<double> e = site_energies(law, chain, s);
  EXPECT_EQ(e[0], 0.0);
  EXPECT_NEAR(e[1], m1 * 0.01 / 2 + phi2 / 2, 1e-6 * e[1]);
  EXPECT_NEAR(e[2], phi2 / 2, 1e-6 * e[2]);
  EXPECT_NEAR(total_energy(law, chain, s), m1 * 0.01 / 2 + phi2, 1e-6 * e[1]);
  // Forces: each bead reads the mean of its two contact forces A[x]_+^{3/2}: bead 0 (0 + 0)/2,
  // bead 1 (0 + A11 (1e-6)^{1.5})/2, bead 2 (A11 (1e-6)^{1.5} + 0)/2.
  const double f2 = a11 * std::pow(1e-6, 1.5);
  const std::vector<double> f = particle_forces(law, s);
  EXPECT_EQ(f[0], 0.0);
  EXPECT_NEAR(f[1], f2 / 2, 1e-6 * f2);
  EXPECT_NEAR(f[2], f2 / 2, 1e-6 * f2);
}

TEST(SiteEnergy, HandValuesUnderPrecompression) {
  // F0 = 10 N: Δ = (F0/A)^{2/3} per bond; φ(x) = (2/5) A [Δ + x]_+^{5/2} − (2/5) A Δ^{5/2} − F0 x.
  // The displacement kick u = (0, α, 0), α = 0.1 µm: x_1 = −α, x_2 = +α, the wall bonds x = 0 (φ = 0).
  const double f0 = 10, alpha = 1e-7;
  const double delta = std::pow(f0 / a11, 2.0 / 3.0);
  const auto phi = [&](double x) {
    return 0.4 * a11 * std::pow(delta + x, 2.5) - 0.4 * a11 * std::pow(delta, 2.5) - f0 * x;
  };
  const Chain chain = fixtures::homogeneous(3, f0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  State s(3);
  s.u = {0, alpha, 0};
  const std::vector<double> e = site_energies(law, chain, s);
  const double phi1 = phi(-alpha), phi2 = phi(alpha);
  EXPECT_NEAR(e[0], phi1 / 2, 1e-5 * e[0]);  // (φ_0 + φ_1)/2, φ_0 = 0
  EXPECT_NEAR(e[1], (phi1 + phi2) / 2, 1e-5 * e[1]);
  EXPECT_NEAR(e[2], phi2 / 2, 1e-5 * e[2]);
  // Forces: the wall bonds carry F0 (Δ_wall = (F0/A_wall)^{2/3} at x = 0); bond 1 A11 (Δ − α)^{3/2},
  // bond 2 A11 (Δ + α)^{3/2}.
  const double f1 = a11 * std::pow(delta - alpha, 1.5), f2 = a11 * std::pow(delta + alpha, 1.5);
  const std::vector<double> f = particle_forces(law, s);
  EXPECT_NEAR(f[0], (f0 + f1) / 2, 1e-6 * f0);
  EXPECT_NEAR(f[1], (f1 + f2) / 2, 1e-6 * f0);
  EXPECT_NEAR(f[2], (f2 + f0) / 2, 1e-6 * f0);
  EXPECT_NEAR(std::pow(f0 / a_wall, 2.0 / 3.0), chain.overlap[0], 1e-6 * chain.overlap[0]);
  // At rest every bead reads F0.
  for (double x : particle_forces(law, State(3))) EXPECT_NEAR(x, f0, 1e-9 * f0);
}

TEST(EnergySpread, OfAFiveBeadSiteEnergyProfile) {
  // The chain's own energies through energy_spread: 5 beads, F0 = 0, only bead 3 moving
  // (v = 0.2 m/s, u = 0): E = (0, 0, 0, m1 0.04/2, 0); about n0 = 1: m̃2 = (3 − 1)² = 4, about
  // the centroid 0, P⁻¹ = 1.
  const Chain chain = fixtures::homogeneous(5, 0.0);
  State s(5);
  s.v[3] = 0.2;
  const std::vector<double> e = site_energies(make_force_law(ForceLawKind::hertz, chain), chain, s);
  EXPECT_NEAR(e[3], m1 * 0.04 / 2, 1e-6 * e[3]);
  const EnergySpread spread = energy_spread(e, 1);
  EXPECT_DOUBLE_EQ(spread.m2_site, 4.0);
  EXPECT_DOUBLE_EQ(spread.m2_centroid, 0.0);
  EXPECT_DOUBLE_EQ(spread.ipr, 1.0);
}

}  // namespace
}  // namespace granular
