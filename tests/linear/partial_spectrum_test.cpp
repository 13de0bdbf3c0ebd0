// The partial-spectrum methods (lapack = dstemr by index, bisect = many-shift Sturm +
// inverse iteration, arpack and slepc = shift-invert Krylov) must give the same modes.
//
// Which IPRs are compared: an eigenvector is only determined up to rotations within eigenvalues
// closer than its accuracy. By Davis–Kahan, a unit vector with residual ‖Tw − λw‖ = r lies within
// angle r/gap of the true eigenvector (gap = distance to the nearest other eigenvalue), and the
// IPR, a smooth quartic form of w, moves by a relative O(10·angle) (the factor covers the power 4
// and the mass weighting m^{-1/2}, whose spread is (m1/m2)^{1/2} ≈ 2.8 here). A mode's IPR is
// compared when 100 · r_max / gap ≤ 1e-8, r_max the larger residual of the two results (floored
// at 1e-16 ‖T‖) — i.e. relative gaps ≳ 1e-6 at the residuals every method reaches. Closer modes
// (clusters of light beads isolated among heavy ones, agreeing to ~1e-16; crowded band edges)
// are compared by eigenvalue only. Tolerances are fixed; each test requires that IPRs were compared.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <hdf5.h>

#include "granular/error.hpp"
#include "granular/files/spectrum_file.hpp"
#include "granular/linear/band_edges.hpp"
#include "granular/linear/detail/lapack_eigensolver.hpp"
#include "granular/linear/detail/shift_invert_eigensolvers.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_ipr.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/named_chains.hpp"

namespace granular {
namespace {

constexpr double kValueTol = 1e-10;  // relative, on ω²
constexpr double kIprTol = 1e-8;     // relative
constexpr double kSafety = 100;      // Davis–Kahan angle → IPR change, see the top

/// The comparison rule above: relative gap (gap/‖T‖) and relative residuals of both results.
bool separated(double relative_gap, double r1, double r2) {
  return kSafety * std::max({r1, r2, 1e-16}) / relative_gap <= kIprTol;
}

DynamicalMatrix make(Disorder disorder, std::size_t n, std::uint64_t seed = 1) {
  return dynamical_matrix(random_chain(disorder, {.N = n, .q = 0.5, .xi = 0.5, .seed = seed}));
}

std::vector<SpectrumMethod> all_methods() {
  std::vector<SpectrumMethod> m{SpectrumMethod::lapack, SpectrumMethod::bisect, SpectrumMethod::arpack};
  if (have_slepc()) m.push_back(SpectrumMethod::slepc);
  return m;
}

/// Relative gap of each eigenvalue of `full` (ascending) to its neighbours.
std::vector<double> relative_gaps(const Eigen::VectorXd& full, double norm) {
  const Eigen::Index n = full.size();
  std::vector<double> g(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    double gap = std::numeric_limits<double>::infinity();
    if (k > 0) gap = std::min(gap, full[k] - full[k - 1]);
    if (k + 1 < n) gap = std::min(gap, full[k + 1] - full[k]);
    g[k] = gap / norm;
  }
  return g;
}

/// Checks `got` against a reference on the same modes; returns how many IPRs were compared.
int expect_same_modes(const Spectrum& ref, const Spectrum& got, const std::vector<double>& gaps,
                      const std::string& what) {
  EXPECT_EQ(got.mode, ref.mode) << what;
  if (got.mode != ref.mode) return 0;
  int compared = 0;
  for (std::size_t j = 0; j < ref.size(); ++j) {
    EXPECT_NEAR(got.omega2[j], ref.omega2[j], kValueTol * ref.omega2[j]) << what << " mode " << ref.mode[j];
    if (separated(gaps[ref.mode[j] - 1], ref.residual[j], got.residual[j])) {
      EXPECT_NEAR(got.ipr[j], ref.ipr[j], kIprTol * ref.ipr[j]) << what << " mode " << ref.mode[j];
      ++compared;
    }
  }
  return compared;
}

void expect_invariants(const Spectrum& p, const SymTridiagonal& t, const std::string& what) {
  for (std::size_t j = 0; j < p.size(); ++j) {
    EXPECT_LE(p.residual[j], 1e-13) << what << " residual of mode " << p.mode[j];
    EXPECT_GT(p.ipr[j], 0.0);
    EXPECT_LE(p.ipr[j], 1.0);
    if (j > 0) {
      EXPECT_LT(p.mode[j - 1], p.mode[j]) << what;
      EXPECT_LE(p.freq_khz[j - 1], p.freq_khz[j]) << what;
    }
  }
  (void)t;
}

struct Case {
  Disorder disorder;
  double near_khz;
  const char* label;
  bool separated_modes_expected;  // false where all 20 modes crowd a band edge (relative gaps < 1e-6)
};

class MethodsAgree : public ::testing::TestWithParam<Case> {};

TEST_P(MethodsAgree, OnTwentyModesOfATenThousandBeadChain) {
  const Case c = GetParam();
  const DynamicalMatrix chain = make(c.disorder, 10000);
  const auto full = LapackEigensolver().solve(chain, false).values;  // for the gaps only
  const auto gaps = relative_gaps(full, chain.max_abs());
  const auto selection = nearest(c.near_khz, 20);
  SpectrumConfig config;
  config.method = SpectrumMethod::lapack;
  const Spectrum ref = spectrum(chain, selection, config);
  ASSERT_EQ(ref.size(), 20u);
  expect_invariants(ref, chain, "lapack");
  for (std::size_t j = 0; j < ref.size(); ++j)
    EXPECT_NEAR(ref.omega2[j], full[ref.mode[j] - 1], kValueTol * full[ref.mode[j] - 1]);
  int compared = 0;
  for (SpectrumMethod m : all_methods()) {
    if (m == SpectrumMethod::lapack) continue;
    config.method = m;
    const Spectrum got = spectrum(chain, selection, config);
    const std::string what = std::string(to_string(m)) + " " + c.label;
    expect_invariants(got, chain, what);
    compared += expect_same_modes(ref, got, gaps, what);
  }
  RecordProperty("iprs_compared", compared);
  std::printf("[ %-11s ] %d IPR comparisons (3 methods against lapack)\n", c.label, compared);
  if (c.separated_modes_expected) {
    EXPECT_GT(compared, 0) << c.label;
  }
}

// Inside a band: 15 kHz (type-1 band; for RDM2 at q = ξ = 0.5 it lies in the gap above the lower
// band, so 10 kHz there). At a band edge: f1 = 18.0883 kHz (docs/physics.md, "The linear spectrum" table; the top of the
// homogeneous spectrum) and, for RDM2, 15 kHz, whose nearest modes are the top of its lower band
// (14.343–14.347 kHz at N = 1e4) — found through the gap, the hard case for shift-invert.
INSTANTIATE_TEST_SUITE_P(EveryDisorder, MethodsAgree,
                         ::testing::Values(Case{Disorder::homogeneous, 15.0, "h_inside", true},
                                           Case{Disorder::homogeneous, 18.0883, "h_edge", false},
                                           Case{Disorder::anderson, 15.0, "A_inside", true},
                                           Case{Disorder::anderson, 18.0883, "A_edge", false},
                                           Case{Disorder::rdm1, 15.0, "RDM1_inside", true},
                                           Case{Disorder::rdm1, 18.0883, "RDM1_edge", false},
                                           Case{Disorder::rdm2, 10.0, "RDM2_inside", true},
                                           Case{Disorder::rdm2, 15.0, "RDM2_edge", false}),
                         [](const auto& info) { return std::string(info.param.label); });

TEST(PartialSpectrum, EqualsTheRowsOfTheFullLapackSpectrum) {
  const DynamicalMatrix chain = make(Disorder::anderson, 2000, 7);
  const auto full = LapackEigensolver().solve(chain, true);
  const auto gaps = relative_gaps(full.values, chain.max_abs());
  for (const auto& selection : {nearest(15.0, 25), window(20.0, 30.0), nearest(35.0, 7)}) {
    for (SpectrumMethod m : all_methods()) {
      SpectrumConfig config;
      config.method = m;
      config.vectors = true;
      const Spectrum p = spectrum(chain, selection, config);
      ASSERT_GT(p.size(), 0u);
      const std::string what(to_string(m));
      expect_invariants(p, chain, what);
      int compared = 0;
      for (std::size_t j = 0; j < p.size(); ++j) {
        const auto row = static_cast<Eigen::Index>(p.mode[j] - 1);
        EXPECT_NEAR(p.omega2[j], full.values[row], kValueTol * full.values[row]) << what;
        EXPECT_DOUBLE_EQ(p.freq_khz[j], frequency_khz(p.omega2[j]));
        if (separated(gaps[row], p.residual[j], 1e-16)) {  // full LAPACK: residual ~ε (dstevr)
          const double ipr_full = displacement_ipr(full.vectors.col(row).data(), chain.inverse_sqrt_mass.data(), 2000);
          EXPECT_NEAR(p.ipr[j], ipr_full, kIprTol * ipr_full) << what << " mode " << p.mode[j];
          ++compared;
        }
      }
      EXPECT_GT(compared, 0) << what;
      if (selection.kind == ModeSelection::Kind::window) {
        // exactly the modes of the full spectrum inside [20, 30] kHz
        std::size_t inside = 0;
        for (Eigen::Index k = 0; k < full.values.size(); ++k) {
          const double f = frequency_khz(full.values[k]);
          inside += f >= 20.0 && f <= 30.0;
        }
        EXPECT_EQ(p.size(), inside) << what;
      } else {
        // the K nearest: no mode left out is nearer than the farthest one kept
        double farthest = 0;
        for (double f : p.freq_khz) farthest = std::max(farthest, std::fabs(f - selection.near_khz));
        for (Eigen::Index k = 0; k < full.values.size(); ++k) {
          const auto mode = static_cast<std::size_t>(k + 1);
          if (std::find(p.mode.begin(), p.mode.end(), mode) != p.mode.end()) continue;
          EXPECT_GE(std::fabs(frequency_khz(full.values[k]) - selection.near_khz), farthest) << what << " mode " << mode;
        }
      }
    }
  }
}

TEST(PartialSpectrum, NearOutsideTheSpectrumGivesTheEdgeModes) {
  const DynamicalMatrix chain = make(Disorder::anderson, 500);
  for (SpectrumMethod m : all_methods()) {
    SpectrumConfig config;
    config.method = m;
    const auto top = spectrum(chain, nearest(1000.0, 5), config);
    ASSERT_EQ(top.size(), 5u) << to_string(m);
    EXPECT_EQ(top.mode.front(), 496u) << to_string(m);
    EXPECT_EQ(top.mode.back(), 500u) << to_string(m);
    const auto bottom = spectrum(chain, nearest(0.0, 3), config);
    ASSERT_EQ(bottom.size(), 3u) << to_string(m);
    EXPECT_EQ(bottom.mode.front(), 1u) << to_string(m);
  }
}

TEST(PartialSpectrum, BadCountsAreErrorsAndEmptyWindowsAreEmpty) {
  const DynamicalMatrix chain = make(Disorder::rdm1, 200);
  for (SpectrumMethod m : all_methods()) {
    SpectrumConfig config;
    config.method = m;
    EXPECT_THROW(spectrum(chain, nearest(15, 0), config), InvalidInput);
    EXPECT_THROW(spectrum(chain, nearest(15, -3), config), InvalidInput);
    EXPECT_THROW(spectrum(chain, nearest(15, 201), config), InvalidInput);
    EXPECT_THROW(spectrum(chain, nearest(-1, 3), config), InvalidInput);
    EXPECT_THROW(spectrum(chain, nearest(std::nan(""), 3), config), InvalidInput);
    EXPECT_THROW(spectrum(chain, window(30, 20), config), InvalidInput);
    // above the spectrum, and a window narrower than any mode spacing
    const auto empty = spectrum(chain, window(100, 200), config);
    EXPECT_EQ(empty.size(), 0u);
    EXPECT_TRUE(empty.mode.empty() && empty.ipr.empty() && empty.freq_khz.empty());
    const auto one = spectrum(chain, nearest(15, 1), config);
    ASSERT_EQ(one.size(), 1u);
    const double f = one.freq_khz[0];
    EXPECT_EQ(spectrum(chain, window(f * (1 + 1e-9), f * (1 + 2e-9)), config).size(), 0u);
  }
  // K = N: the whole spectrum, with LAPACK; the Krylov methods need K <= N - 1 and say so.
  SpectrumConfig config;
  EXPECT_EQ(spectrum(chain, nearest(15, 200), config).size(), 200u);
  config.method = SpectrumMethod::bisect;
  EXPECT_EQ(spectrum(chain, nearest(15, 200), config).size(), 200u);
  config.method = SpectrumMethod::arpack;
  EXPECT_THROW(spectrum(chain, nearest(15, 200), config), InvalidInput);
}

TEST(PartialSpectrum, ParsesMethodNames) {
  EXPECT_THROW(parse_spectrum_method("lapak"), InvalidInput);
  EXPECT_EQ(parse_spectrum_method("slepc"), SpectrumMethod::slepc);
  EXPECT_EQ(parse_spectrum_method("fast"), SpectrumMethod::fast);
}

TEST(PartialSpectrum, WritesEigenvectorsToHdf5) {
  const DynamicalMatrix chain = make(Disorder::anderson, 300);
  SpectrumConfig config;
  config.vectors = true;
  const auto p = spectrum(chain, nearest(20, 4), config);
  const std::string path = std::string(GRANULAR_BINARY_DIR) + "/partial_spectrum_test.h5";
  ;
  write_spectrum_hdf5(path, p, chain)->commit();
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t set = H5Dopen2(file, "eigenvectors", H5P_DEFAULT);
  ASSERT_GE(set, 0);
  const hid_t space = H5Dget_space(set);
  hsize_t dims[2] = {0, 0};
  ASSERT_EQ(H5Sget_simple_extent_ndims(space), 2);
  H5Sget_simple_extent_dims(space, dims, nullptr);
  EXPECT_EQ(dims[0], 4u);
  EXPECT_EQ(dims[1], 300u);
  std::vector<double> data(4 * 300);
  ASSERT_GE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), 0);
  for (int j = 0; j < 4; ++j) {
    EXPECT_DOUBLE_EQ(displacement_ipr(&data[j * 300], chain.inverse_sqrt_mass.data(), 300),
                     p.ipr[j]);  // row j is mode j
    EXPECT_DOUBLE_EQ(data[j * 300 + 17], p.vector(static_cast<std::size_t>(j))[17]);
  }
  H5Sclose(space);
  H5Dclose(set);
  H5Fclose(file);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace granular
