// Every mode of a crystal by dense LAPACK, checked by invariants: D w = ω² w with orthonormal w,
// the trace, the frequencies' units, and the two zero modes of a torus (docs/crystals.md, "Spectra").
#include "granular/crystal/crystal_spectrum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "granular/crystal/static_state.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

TEST(CrystalSpectrum, EigenpairsOfADisorderedHexagonalCrystalWithWalls) {
  PackingSpec spec;
  spec.lattice = Lattice::hexagonal, spec.Lx = 7, spec.Ly = 6;
  const Packing p = make_packing(disordered(spec, {.kind = PackingDisorder::Kind::mass, .width = 0.6, .seed = 8}));
  const CrystalMatrix d = crystal_matrix(p, static_state(p));
  const CrystalSpectrum s = crystal_spectrum(d, {.vectors = true});
  const std::size_t n = d.rows();
  ASSERT_EQ(s.size(), n);
  ASSERT_EQ(s.vectors.size(), n * n);
  const std::vector<double> a = dense(d);
  double trace = 0, sum = 0, worst_residual = 0, worst_orthogonality = 0;
  for (std::size_t r = 0; r < n; ++r) trace += a[r * n + r];
  for (std::size_t k = 0; k < n; ++k) {
    sum += s.omega2[k];
    const double* w = s.vectors.data() + k * n;
    for (std::size_t r = 0; r < n; ++r) {
      double dw = 0;
      for (std::size_t c = 0; c < n; ++c) dw += a[r * n + c] * w[c];
      worst_residual = std::max(worst_residual, std::fabs(dw - s.omega2[k] * w[r]) / s.omega2.back());
    }
    for (std::size_t l = k; l < std::min(n, k + 3); ++l) {
      double dot = 0;
      for (std::size_t r = 0; r < n; ++r) dot += w[r] * s.vectors[l * n + r];
      worst_orthogonality = std::max(worst_orthogonality, std::fabs(dot - (k == l ? 1.0 : 0.0)));
    }
    EXPECT_NEAR(s.freq_hz[k], std::sqrt(s.omega2[k]) / (2 * std::numbers::pi), 1e-12 * s.freq_hz[k]);
    EXPECT_GE(s.ipr[k], 1.0 / static_cast<double>(p.size()) * (1 - 1e-12));
    EXPECT_LE(s.ipr[k], 1.0);
  }
  EXPECT_LT(worst_residual, 1e-13);
  EXPECT_LT(worst_orthogonality, 1e-13);
  EXPECT_NEAR(sum, trace, 1e-12 * trace);
  EXPECT_GT(s.omega2.front(), 0);  // the walls hold every mode: the packing is rigid
  EXPECT_TRUE(crystal_spectrum(d).vectors.empty());
}

TEST(CrystalSpectrum, ATorusHasTwoZeroModesAndSignedUnstableFrequencies) {
  PackingSpec spec;
  spec.lattice = Lattice::hexagonal, spec.boundary = Boundary::periodic, spec.Lx = 6, spec.Ly = 4, spec.strain = 1e-3;
  const CrystalSpectrum hex = crystal_spectrum(crystal_matrix(make_packing(spec), static_state(make_packing(spec))));
  const double top = hex.omega2.back();
  EXPECT_LT(std::fabs(hex.omega2[0]), 1e-12 * top);
  EXPECT_LT(std::fabs(hex.omega2[1]), 1e-12 * top);
  EXPECT_GT(hex.omega2[2], 1e-3 * top);
  spec.lattice = Lattice::square;
  const Packing square = make_packing(spec);
  const CrystalSpectrum s = crystal_spectrum(crystal_matrix(square, static_state(square, {.require_rigid = false})));
  ASSERT_LT(s.omega2.front(), 0);
  EXPECT_DOUBLE_EQ(s.freq_hz.front(), -std::sqrt(-s.omega2.front()) / (2 * std::numbers::pi));
}

// A light bead in a hexagonal torus has a mode above the perfect crystal's band, localized on it:
// its IPR is O(1) where every Bloch wave's is 1/N (equal amplitudes on every bead).
TEST(CrystalSpectrum, ALightImpurityHasALocalizedModeAboveTheBand) {
  PackingSpec spec;
  spec.lattice = Lattice::hexagonal, spec.boundary = Boundary::periodic, spec.Lx = 9, spec.Ly = 8, spec.strain = 1e-3;
  const Packing perfect = make_packing(spec);
  const CrystalSpectrum bloch = crystal_spectrum(crystal_matrix(perfect, static_state(perfect)));
  spec.materials.assign(72, spec.material);
  spec.materials[40].density *= 0.2;  // same size and stiffness: the static state is the lattice's
  const Packing p = make_packing(spec);
  const CrystalSpectrum s = crystal_spectrum(crystal_matrix(p, static_state(p)));
  EXPECT_GT(s.freq_hz.back(), 1.2 * bloch.freq_hz.back());
  EXPECT_GT(s.ipr.back(), 0.5);  // 0.96: nearly the light bead alone
  double widest = 0;
  for (std::size_t k = 2; k < bloch.size(); ++k) widest = std::max(widest, bloch.ipr[k]);
  RecordProperty("impurity_ipr", format_number(s.ipr.back()));
  RecordProperty("widest_bloch_ipr", format_number(widest));
  // Bloch waves spread over the torus; a degenerate level mixes them in a basis LAPACK picks, so
  // only a loose bound: 6/N.
  EXPECT_LT(widest, 6.0 / 72);
}

TEST(CrystalSpectrum, RefusesACrystalTooLargeForEveryModeBeforeAllocating) {
  CrystalMatrix d;  // 20000 beads: dsyevd's workspace would pass 2^31 doubles
  d.matrix.n = 40000;
  d.matrix.row_start.assign(d.rows() + 1, 0);
  d.inverse_sqrt_mass.assign(20000, 1.0);
  try {
    crystal_spectrum(d);
    ADD_FAILURE() << "20000 beads accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "N");
    EXPECT_NE(std::string(e.what()).find("crystal_nearest_modes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace granular
