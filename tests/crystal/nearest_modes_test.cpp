// The modes nearest a frequency by ARPACK shift-invert on the sparse matrix equal the dense
// solver's: frequencies to 1e-10, eigenvectors by subspace angle (docs/crystals.md, "Spectra").
#include "granular/crystal/nearest_modes.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <tuple>
#include <vector>

#include "granular/crystal/crystal_case.hpp"
#include "granular/crystal/static_state.hpp"
#include "granular/error.hpp"
#include "granular/linear/detail/shift_invert_eigensolvers.hpp"

namespace granular {
namespace {

TEST(NearestModes, EqualTheDenseModesOfADisorderedHexagonalCrystal) {
  PackingSpec spec;
  spec.lattice = Lattice::hexagonal, spec.Lx = 12, spec.Ly = 12;
  const Packing p = make_packing(disordered(spec, {.kind = PackingDisorder::Kind::mass, .width = 0.5, .seed = 12}));
  const CrystalMatrix d = crystal_matrix(p, static_state(p));
  const CrystalSpectrum all = crystal_spectrum(d, {.vectors = true});
  const std::size_t n = d.rows();
  for (double fraction : {0.05, 0.5, 0.9}) {
    // A target between two modes, so the selection is not decided by rounding.
    const auto m = static_cast<std::size_t>(fraction * static_cast<double>(n));
    const double near = 0.5 * (all.freq_hz[m] + all.freq_hz[m + 1]);
    const long count = 10;
    const CrystalSpectrum some = crystal_nearest_modes(d, near, count, {.vectors = true});
    ASSERT_EQ(some.size(), 10u);
    EXPECT_LT(some.max_residual, 1e-12) << "fraction " << fraction;
    const double sigma = std::pow(2 * std::numbers::pi * near, 2);
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return std::fabs(all.omega2[a] - sigma) < std::fabs(all.omega2[b] - sigma);
    });
    order.resize(10);
    std::sort(order.begin(), order.end());
    Eigen::MatrixXd dense_vectors(n, 10), arpack_vectors(n, 10);
    for (std::size_t k = 0; k < 10; ++k) {
      EXPECT_NEAR(some.freq_hz[k], all.freq_hz[order[k]], 1e-10 * all.freq_hz[order[k]]) << "fraction " << fraction;
      EXPECT_NEAR(some.ipr[k], all.ipr[order[k]], 1e-6) << "fraction " << fraction;
      for (std::size_t r = 0; r < n; ++r) {
        dense_vectors(static_cast<long>(r), static_cast<long>(k)) = all.vectors[order[k] * n + r];
        arpack_vectors(static_cast<long>(r), static_cast<long>(k)) = some.vectors[k * n + r];
      }
    }
    // Cosines of the principal angles between the two 10-dimensional subspaces.
    const Eigen::VectorXd cosines = (dense_vectors.transpose() * arpack_vectors).jacobiSvd().singularValues();
    EXPECT_GT(cosines.minCoeff(), 1 - 1e-10) << "fraction " << fraction;
  }
}

TEST(NearestModes, RefusesABadTargetOrCount) {
  PackingSpec spec;
  spec.Lx = 3, spec.Ly = 3;
  const Packing p = make_packing(spec);
  const CrystalMatrix d = crystal_matrix(p, static_state(p));
  const double top = crystal_spectrum(d).freq_hz.back();
  for (auto [near, count, name] :
       {std::tuple{-1.0, 2L, "near"}, {1e3, 0L, "count"}, {1e3, 18L, "count"}, {3 * top, 2L, "near"}}) {
    try {
      crystal_nearest_modes(d, near, count);
      ADD_FAILURE() << name << " " << near;
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.parameter(), name);
    }
  }
  // The bound refuses only what lies beyond the spectrum: its own top mode is a valid target.
  EXPECT_NEAR(crystal_nearest_modes(d, top, 2).freq_hz.back(), top, 1e-9 * top);
}

// 10⁴ beads, beyond the dense solver's comfort: the static state balances and the 20 modes nearest
// 10 kHz solve D w = ω² w to 1e-10 of max |D_ij|, with orthonormal vectors.
TEST(Long_NearestModes, TenThousandBeadHexagonalCrystal) {
  PackingSpec spec;
  spec.lattice = Lattice::hexagonal, spec.Lx = 100, spec.Ly = 100;
  const Packing p = make_packing(disordered(spec, {.kind = PackingDisorder::Kind::mass, .width = 0.5, .seed = 1}));
  const StaticState state = static_state(p);
  EXPECT_LE(state.imbalance, 1e-13);
  const CrystalMatrix d = crystal_matrix(p, state);
  const CrystalSpectrum m = crystal_nearest_modes(d, 10e3, 20, {.vectors = true});
  ASSERT_EQ(m.size(), 20u);
  double scale = 0, worst = 0;
  for (double v : d.matrix.value) scale = std::max(scale, std::fabs(v));
  for (std::size_t k = 0; k < m.size(); ++k) {
    const double* w = m.vectors.data() + k * d.rows();
    for (std::size_t r = 0; r < d.rows(); ++r) {
      double dw = 0;
      for (auto q = d.matrix.row_start[r]; q < d.matrix.row_start[r + 1]; ++q)
        dw += d.matrix.value[static_cast<std::size_t>(q)] *
              w[static_cast<std::size_t>(d.matrix.column[static_cast<std::size_t>(q)])];
      worst = std::max(worst, std::fabs(dw - m.omega2[k] * w[r]) / scale);
    }
    double norm = 0;
    for (std::size_t r = 0; r < d.rows(); ++r) norm += w[r] * w[r];
    EXPECT_NEAR(norm, 1.0, 1e-12);
    EXPECT_NEAR(m.freq_hz[k], 10e3, 200.0);  // they lie within ±6 Hz: 200 Hz guards the selection only
  }
  EXPECT_LT(worst, 1e-10);
}

}  // namespace
}  // namespace granular

namespace granular {
namespace {

// automatic: ARPACK below 10⁵ beads (the faster there), SLEPc from 10⁵ where the build has it; a
// method named stays itself.
TEST(NearestModes, AutomaticMethodTakesSlepcFromOneHundredThousandBeads) {
  EXPECT_EQ(nearest_method_for(NearestMethod::automatic, slepc_from_beads - 1), NearestMethod::arpack);
  EXPECT_EQ(nearest_method_for(NearestMethod::automatic, slepc_from_beads),
            have_slepc() ? NearestMethod::slepc : NearestMethod::arpack);
  EXPECT_EQ(nearest_method_for(NearestMethod::arpack, 10 * slepc_from_beads), NearestMethod::arpack);
  EXPECT_EQ(nearest_method_for(NearestMethod::slepc, 4), NearestMethod::slepc);
  EXPECT_EQ(CrystalCase{}.method, NearestMethod::automatic);
}

}  // namespace
}  // namespace granular
