// Periodic crystals under a uniform strain against their Bloch dispersion: every eigenvalue of D,
// signed, equals the analytic ω² at the wave vectors the torus allows, and the hexagonal crystal's
// two branches meet at the zone corner K (docs/crystals.md, "Bloch waves").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "granular/crystal/crystal_matrix.hpp"
#include "granular/crystal/crystal_spectrum.hpp"
#include "granular/crystal/static_state.hpp"
#include "granular/model/contact_law.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

struct BlochCrystal {
  Packing packing;
  CrystalSpectrum spectrum;
  double kn = 0, prestress = 0, mass = 0;  // k_n [N/m], f/d [N/m], m [kg]
};

BlochCrystal bloch_crystal(Lattice lattice, long Lx, long Ly, double strain) {
  PackingSpec spec;
  spec.lattice = lattice, spec.boundary = Boundary::periodic, spec.Lx = Lx, spec.Ly = Ly, spec.strain = strain;
  BlochCrystal c{make_packing(spec), {}, 0, 0, 0};
  const StaticState state = static_state(c.packing, {.require_rigid = false});
  EXPECT_EQ(state.iterations, 0);  // the perfect lattice is balanced as it stands
  c.spectrum = crystal_spectrum(crystal_matrix(c.packing, state));
  const double A = hertz_coefficient(steel, spec.radius, steel, spec.radius);
  c.kn = hertz_stiffness(A, c.packing.uniform_overlap);
  c.prestress = hertz_force(A, c.packing.uniform_overlap) / c.packing.spacing;
  c.mass = c.packing.mass[0];
  return c;
}

// Eigenvalues of the 2 × 2 Bloch matrix (2/m) Σ_e (1 − cos q·a e) [k_n e eᵀ − (f/d)(I − e eᵀ)] over
// the bond directions e (one per ± pair).
void bloch_eigenvalues(const BlochCrystal& c, const std::vector<std::array<double, 2>>& bonds, double qx, double qy,
                       std::vector<double>& out) {
  double xx = 0, xy = 0, yy = 0;
  const double a = c.packing.spacing;
  for (const auto& e : bonds) {
    const double w = 2 * (1 - std::cos(a * (qx * e[0] + qy * e[1]))) / c.mass;
    xx += w * (c.kn * e[0] * e[0] - c.prestress * (1 - e[0] * e[0]));
    xy += w * (c.kn + c.prestress) * e[0] * e[1];
    yy += w * (c.kn * e[1] * e[1] - c.prestress * (1 - e[1] * e[1]));
  }
  const double mean = (xx + yy) / 2, radius = std::hypot((xx - yy) / 2, xy);
  out.push_back(mean - radius), out.push_back(mean + radius);
}

// max |λ_numeric − λ_Bloch| / max |λ| over the sorted lists: a dense solver's eigenvalues are
// accurate to ε‖D‖, not to ε|λ| for the smallest.
double worst_difference(std::vector<double> analytic, const std::vector<double>& numeric) {
  std::sort(analytic.begin(), analytic.end());
  EXPECT_EQ(analytic.size(), numeric.size());
  double scale = 0, worst = 0;
  for (double v : numeric) scale = std::max(scale, std::fabs(v));
  for (std::size_t k = 0; k < std::min(analytic.size(), numeric.size()); ++k)
    worst = std::max(worst, std::fabs(analytic[k] - numeric[k]) / scale);
  return worst;
}

TEST(BlochDispersion, SquareEigenvaluesAreTheAnalyticOnesSignedAt1e10) {
  const long Lx = 6, Ly = 5;
  const BlochCrystal c = bloch_crystal(Lattice::square, Lx, Ly, 1e-3);
  std::vector<double> analytic;
  for (long n1 = 0; n1 < Lx; ++n1)
    for (long n2 = 0; n2 < Ly; ++n2) {
      const double cx = 1 - std::cos(2 * std::numbers::pi * static_cast<double>(n1) / static_cast<double>(Lx));
      const double cy = 1 - std::cos(2 * std::numbers::pi * static_cast<double>(n2) / static_cast<double>(Ly));
      // D(q) is diagonal: ω²_x = (2/m)[k_n (1 − cos q·a1) − (f/d)(1 − cos q·a2)], ω²_y alike.
      analytic.push_back(2 / c.mass * (c.kn * cx - c.prestress * cy));
      analytic.push_back(2 / c.mass * (c.kn * cy - c.prestress * cx));
    }
  const double worst = worst_difference(analytic, c.spectrum.omega2);
  RecordProperty("worst_relative_difference", format_number(worst));
  EXPECT_LT(worst, 1e-10);
  // The compressed periodic square lattice is unstable: q along a row, polarized across it.
  // min ω² = −(4/m)(f/d) at q = (π/a, 0) (Lx even), polarized across the rows.
  const double unstable = -4 / c.mass * c.prestress;
  EXPECT_NEAR(c.spectrum.omega2.front(), unstable, 1e-10 * c.spectrum.omega2.back());
  EXPECT_LT(unstable, 0);
}

TEST(BlochDispersion, HexagonalEigenvaluesAndTheDiracDegeneracyAtK) {
  const long Lx = 12, Ly = 8;  // Lx a multiple of 3: K = (4π/3a, 0) is allowed
  const BlochCrystal c = bloch_crystal(Lattice::hexagonal, Lx, Ly, 1e-3);
  const double a = c.packing.spacing, s60 = std::numbers::sqrt3 / 2;
  const std::vector<std::array<double, 2>> bonds{{1, 0}, {0.5, s60}, {-0.5, s60}};
  // The torus's periods are Lx a (1, 0) and Ly (√3/2) a (0, 1): q = 2π (n1 / (Lx a), n2 / (Ly √3 a / 2)),
  // n1 < Lx, n2 < Ly, is one wave vector of each class modulo the reciprocal lattice.
  std::vector<double> analytic;
  for (long n1 = 0; n1 < Lx; ++n1)
    for (long n2 = 0; n2 < Ly; ++n2)
      bloch_eigenvalues(c, bonds, 2 * std::numbers::pi * static_cast<double>(n1) / (static_cast<double>(Lx) * a),
                        2 * std::numbers::pi * static_cast<double>(n2) / (static_cast<double>(Ly) * s60 * a), analytic);
  const double worst = worst_difference(analytic, c.spectrum.omega2);
  RecordProperty("worst_relative_difference", format_number(worst));
  EXPECT_LT(worst, 1e-10);
  EXPECT_GT(c.spectrum.omega2[2], 0);  // the hexagonal crystal is stable: two zero modes (translations) only

  // At K, Σ_e (1 − cos K·a e) e eᵀ = (9/4) I: D(K) = (9/2m)(k_n − f/d) I, twice (K and −K) doubly.
  std::vector<double> at_k;
  bloch_eigenvalues(c, bonds, 4 * std::numbers::pi / (3 * a), 0, at_k);
  const double expected = 9 / (2 * c.mass) * (c.kn - c.prestress);
  EXPECT_NEAR(at_k[0], expected, 1e-12 * expected);
  EXPECT_NEAR(at_k[1], expected, 1e-12 * expected);
  const double scale = c.spectrum.omega2.back();
  long numeric = 0, bloch = 0;
  for (double v : c.spectrum.omega2) numeric += std::fabs(v - expected) < 1e-10 * scale;
  for (double v : analytic) bloch += std::fabs(v - expected) < 1e-10 * scale;
  EXPECT_GE(numeric, 4);
  EXPECT_EQ(numeric, bloch);
}

}  // namespace
}  // namespace granular
