// SLEPc's shift-invert modes of a 2000-bead disordered hexagonal crystal (4000 rows) equal the
// dense LAPACK modes of the same matrix, on 1, 2 and 4 MPI ranks (docs/crystals.md, "Spectra"):
// frequencies to 1e-10 relative, eigenvectors by the principal angles between the two sets.
// Long (about 20 s, most of it the dense solve): pass 1 of the test command runs it, the
// sanitizer pass does not (CrystalTool.NearestModes* runs the same path there on 144 beads).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

#include "granular/crystal/nearest_modes.hpp"
#include "granular/crystal/static_state.hpp"
#include "granular/linear/detail/shift_invert_eigensolvers.hpp"
#include "granular/parallel/mpi_context.hpp"

namespace granular {
namespace {

constexpr long crystal_slepc_count = 12;

CrystalMatrix crystal_slepc_matrix() {  // 50 × 40 beads, mass disorder w = 0.5, walls at F0 = 10 N
  PackingSpec spec;
  spec.lattice = Lattice::hexagonal, spec.Lx = 50, spec.Ly = 40;
  const Packing p = make_packing(disordered(spec, {.kind = PackingDisorder::Kind::mass, .width = 0.5, .seed = 5}));
  return crystal_matrix(p, static_state(p));
}

/// The modes' ω² followed by their vectors, as one array (what a child rank hands back).
std::vector<double> crystal_slepc_flat(const CrystalSpectrum& s) {
  std::vector<double> flat = s.omega2;
  flat.insert(flat.end(), s.vectors.begin(), s.vectors.end());
  return flat;
}

/// `flat` (crystal_slepc_flat of `count` modes of `rows`-row vectors) against the dense modes
/// nearest σ: values to 1e-10 relative, every principal angle's cosine ≥ 1 − 1e-10.
void expect_dense_modes(const std::vector<double>& flat, const CrystalSpectrum& dense, double sigma,
                        const std::string& what) {
  const auto rows = static_cast<Eigen::Index>(dense.omega2.size());
  ASSERT_EQ(flat.size(), static_cast<std::size_t>(crystal_slepc_count * (1 + rows))) << what;
  std::vector<std::size_t> order(dense.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::fabs(dense.omega2[a] - sigma) < std::fabs(dense.omega2[b] - sigma);
  });
  order.resize(crystal_slepc_count);
  std::sort(order.begin(), order.end());
  Eigen::MatrixXd expected(rows, crystal_slepc_count), found(rows, crystal_slepc_count);
  for (Eigen::Index j = 0; j < crystal_slepc_count; ++j) {
    const std::size_t k = order[static_cast<std::size_t>(j)];
    EXPECT_NEAR(flat[static_cast<std::size_t>(j)], dense.omega2[k], 1e-10 * dense.omega2[k]) << what << " mode " << j;
    expected.col(j) = Eigen::Map<const Eigen::VectorXd>(dense.vectors.data() + k * dense.size(), rows);
    found.col(j) = Eigen::Map<const Eigen::VectorXd>(flat.data() + crystal_slepc_count + j * rows, rows);
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> overlap(expected.transpose() * found);
  EXPECT_GE(overlap.singularValues().minCoeff(), 1 - 1e-10) << what;
  EXPECT_LE(overlap.singularValues().maxCoeff(), 1 + 1e-10) << what;
}

// Run by the test below under mpiexec -np P (skipped when run alone): every rank solves, rank 0
// writes the flat result to the file GRANULAR_CRYSTAL_SLEPC_CHILD names.
TEST(CrystalSlepcOnRanks, Child) {
  const char* path = std::getenv("GRANULAR_CRYSTAL_SLEPC_CHILD");
  if (path == nullptr) GTEST_SKIP() << "run by Long_CrystalSlepc.EqualsTheDenseModesOnOneTwoAndFourRanks";
  const double near_hz = std::strtod(std::getenv("GRANULAR_CRYSTAL_SLEPC_NEAR_HZ"), nullptr);
  const CrystalSpectrum s = crystal_nearest_modes(crystal_slepc_matrix(), near_hz, crystal_slepc_count,
                                                  {.vectors = true}, NearestMethod::slepc);
  if (!MpiContext::instance().root()) return;
  const std::vector<double> flat = crystal_slepc_flat(s);
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(flat.data()), static_cast<std::streamsize>(flat.size() * sizeof(double)));
}

TEST(Long_CrystalSlepc, EqualsTheDenseModesOnOneTwoAndFourRanks) {
  if (!have_slepc()) GTEST_SKIP() << "this build has no SLEPc";
  const CrystalMatrix d = crystal_slepc_matrix();
  ASSERT_EQ(d.rows(), 4000U);
  const CrystalSpectrum dense = crystal_spectrum(d, {.vectors = true});
  // A target between two levels in the upper half, so the nearest 12 are one well-defined set.
  const std::size_t m = 3 * d.rows() / 5;
  const double near_hz = 0.5 * (dense.freq_hz[m] + dense.freq_hz[m + 1]);
  const double sigma = std::pow(2 * std::acos(-1.0) * near_hz, 2);
  const CrystalSpectrum one =
      crystal_nearest_modes(d, near_hz, crystal_slepc_count, {.vectors = true}, NearestMethod::slepc);
  expect_dense_modes(crystal_slepc_flat(one), dense, sigma, "1 rank");
#ifdef GRANULAR_MPIEXEC_PATH
  const std::string dir = (std::filesystem::temp_directory_path() / "granular-crystal-slepc").string();
  std::filesystem::create_directories(dir);
  char near[32];
  std::snprintf(near, sizeof near, "%.17g", near_hz);
  for (int ranks : {2, 4}) {  // 4 ranks on 2 cores: oversubscribed, slower, the same split logic
    const std::string out = dir + "/" + std::to_string(ranks) + ".f64";
    std::filesystem::remove(out);
    // A process that has run SLEPc is an MPI singleton whose OMPI_/PMIX_ variables would confuse
    // the mpiexec it starts: unset them first.
    const std::string command =
        "for v in $(env | sed -n 's/^\\(OMPI_[^=]*\\|PMIX_[^=]*\\)=.*/\\1/p'); do unset $v; done; "
        "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 GRANULAR_CRYSTAL_SLEPC_CHILD=" +
        out + " GRANULAR_CRYSTAL_SLEPC_NEAR_HZ=" + near + " " + std::string(GRANULAR_MPIEXEC_PATH) +
        " --oversubscribe -np " + std::to_string(ranks) + " " +
        std::filesystem::read_symlink("/proc/self/exe").string() +
        " --gtest_filter=CrystalSlepcOnRanks.Child > /dev/null 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << ranks << " ranks";
    std::ifstream in(out, std::ios::binary);
    std::vector<double> flat(static_cast<std::size_t>(crystal_slepc_count) * (1 + d.rows()));
    in.read(reinterpret_cast<char*>(flat.data()), static_cast<std::streamsize>(flat.size() * sizeof(double)));
    ASSERT_TRUE(in) << ranks << " ranks: " << out << " is short";
    expect_dense_modes(flat, dense, sigma, std::to_string(ranks) + " ranks");
  }
  std::filesystem::remove_all(dir);
#endif
}

}  // namespace
}  // namespace granular
