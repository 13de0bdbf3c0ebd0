// The contact block K = k_n n nᵀ − (f/d)(I − n nᵀ) against a finite-difference Hessian of the Hertz
// energy of a rotated pair, and the assembled matrix's symmetry (docs/crystals.md).
#include "granular/crystal/crystal_matrix.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "granular/crystal/detail/contact_kinematics.hpp"
#include "granular/model/contact_law.hpp"

namespace granular {
namespace {

// Hertz energy (2/5) A δ^{5/2} of two beads at absolute positions, in long double from the centre
// distance itself: independent of the library's displacement form of the overlap.
long double pair_energy(long double A, long double radii, const long double (&x)[4]) {
  const long double d = std::hypot(x[2] - x[0], x[3] - x[1]);
  const long double delta = radii - d;
  return delta > 0 ? 0.4L * A * delta * delta * std::sqrt(delta) : 0.0L;
}

TEST(CrystalMatrix, PrestressTermMatchesAFiniteDifferenceHessianOfARotatedPair) {
  const double R = 4.76e-3, A = hertz_coefficient(steel, R, steel, R), theta = 0.7;
  const double delta0 = 1.2e-5;  // ~300 N: a strong prestress f/d
  Packing p;
  p.boundary = Boundary::periodic, p.Lx = 2, p.Ly = 1;
  p.spacing = 2 * R - delta0, p.radius = {R, R}, p.mass = {1, 1}, p.material = {steel, steel};
  p.x = {0, p.spacing * std::cos(theta)}, p.y = {0, p.spacing * std::sin(theta)};
  p.contacts = {{0, 1, std::cos(theta), std::sin(theta), A, delta0}};
  // The state by hand: the pair is not in equilibrium, and the Hessian does not need it to be.
  StaticState s;
  s.ux = {0, 0}, s.uy = {0, 0};
  const auto g = detail::planar_contact(p.contacts[0], p.spacing, 0, 0);
  s.overlap = {g.overlap}, s.distance = {g.distance}, s.nx = {g.nx}, s.ny = {g.ny};
  s.force = {hertz_force(A, g.overlap)}, s.stiffness = {hertz_stiffness(A, g.overlap)};
  const std::vector<double> K = dense(crystal_matrix(p, s));  // m = 1 kg: D = K

  // Central second differences at h and 2h, Richardson-extrapolated: error O(h⁴/δ⁴) + rounding.
  const long double h = 1e-8L;
  const long double x0[4] = {0, 0, p.x[1], p.y[1]};
  auto second = [&](int a, int b, long double step) {
    auto at = [&](long double da, long double db) {
      long double x[4] = {x0[0], x0[1], x0[2], x0[3]};
      x[a] += da, x[b] += db;
      return pair_energy(A, 2.0L * R, x);
    };
    return (at(step, step) - at(step, -step) - at(-step, step) + at(-step, -step)) / (4 * step * step);
  };
  std::vector<double> fd(16);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      fd[static_cast<std::size_t>(4 * a + b)] = static_cast<double>((4 * second(a, b, h) - second(a, b, 2 * h)) / 3);

  // Project bead 1's block on the normal n and the tangent t: k_n and −f/d.
  const double n[2] = {std::cos(theta), std::sin(theta)}, t[2] = {-n[1], n[0]};
  auto project = [](const std::vector<double>& m, const double* u, const double* v) {
    double sum = 0;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) sum += u[a] * m[static_cast<std::size_t>(4 * (2 + a) + 2 + b)] * v[b];
    return sum;
  };
  const double kn = s.stiffness[0], transverse = -s.force[0] / s.distance[0];
  EXPECT_LT(transverse, 0);  // the prestress lowers the transverse stiffness
  EXPECT_NEAR(project(K, t, t), transverse, 1e-12 * std::fabs(transverse));
  EXPECT_NEAR(project(fd, t, t), transverse, 1e-6 * std::fabs(transverse));
  EXPECT_NEAR(project(fd, n, n), kn, 1e-6 * kn);
  EXPECT_NEAR(project(fd, n, t), 0, 1e-6 * std::fabs(transverse));
  for (std::size_t k = 0; k < 16; ++k) EXPECT_NEAR(K[k], fd[k], 1e-6 * std::fabs(transverse)) << "entry " << k;
}

TEST(CrystalMatrix, IsSymmetricToTheBitWithRowsSummingToTheWallsOnly) {
  PackingSpec spec;
  spec.lattice = Lattice::hexagonal, spec.Lx = 6, spec.Ly = 4;
  const Packing p = make_packing(disordered(spec, {.kind = PackingDisorder::Kind::material, .width = 0.3, .seed = 9}));
  const CrystalMatrix d = crystal_matrix(p, static_state(p));
  ASSERT_EQ(d.rows(), 2 * p.size());
  ASSERT_EQ(d.matrix.row_start.size(), d.rows() + 1);
  const std::vector<double> a = dense(d);
  for (std::size_t r = 0; r < d.rows(); ++r) {
    for (std::size_t c = 0; c < d.rows(); ++c) ASSERT_EQ(a[r * d.rows() + c], a[c * d.rows() + r]);
    for (auto k = d.matrix.row_start[r] + 1; k < d.matrix.row_start[r + 1]; ++k)
      EXPECT_LT(d.matrix.column[static_cast<std::size_t>(k - 1)], d.matrix.column[static_cast<std::size_t>(k)]);
  }
  // Rigid translations are free but for the walls: K·(1, 0, 1, 0, …) has only the wall terms.
  std::vector<double> wall_xx(p.size(), 0.0);
  for (std::size_t k = 0; k < p.wall_contacts.size(); ++k) {
    const WallSide w = p.wall_contacts[k].wall;
    if (w == WallSide::left || w == WallSide::right) wall_xx[p.wall_contacts[k].bead] += 1;
  }
  for (std::size_t b = 0; b < p.size(); ++b) {
    double row = 0, scale = 0;
    for (std::size_t c = 0; c < p.size(); ++c) {
      const double v = a[2 * b * d.rows() + 2 * c] / (d.inverse_sqrt_mass[b] * d.inverse_sqrt_mass[c]);
      row += v, scale += std::fabs(v);
    }
    if (wall_xx[b] == 0) {
      EXPECT_NEAR(row, 0, 1e-13 * scale) << "bead " << b;
    }
  }
}

}  // namespace
}  // namespace granular
