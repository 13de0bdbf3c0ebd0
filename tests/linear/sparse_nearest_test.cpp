// Sparse symmetric matrices (linear/sparse_symmetric.hpp) and their SLEPc shift-invert
// eigenpairs nearest a shift, against a dense eigensolver of the same matrix (Eigen's, a method
// independent of SLEPc's Krylov–Schur and MUMPS), on one MPI rank and on two.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "granular/error.hpp"
#include "granular/linear/detail/shift_invert_eigensolvers.hpp"
#include "granular/linear/sparse_symmetric.hpp"

namespace granular {
namespace {

/// The mass-weighted stiffness matrix of a Lx × Ly square net of point masses in the plane with
/// springs of random stiffness to their 4 neighbours and 2 diagonal neighbours, each end tied to
/// the frame beyond the net: positive definite, generic (no degenerate eigenvalues).
SparseSymmetric sparse_net(int lx, int ly, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> stiffness(0.5, 1.5), mass(0.5, 2.0);
  const auto node = [&](int x, int y) { return static_cast<std::size_t>(y * lx + x); };
  const std::size_t n = 2 * static_cast<std::size_t>(lx * ly);
  std::vector<double> m(n / 2);
  for (double& v : m) v = mass(random);
  std::vector<std::size_t> rows, cols;
  std::vector<double> values;
  const auto add = [&](std::size_t i, std::size_t j, double v) {
    rows.push_back(i), cols.push_back(j), values.push_back(v / std::sqrt(m[i / 2] * m[j / 2]));
  };
  const auto spring = [&](int x, int y, int dx, int dy) {
    const double k = stiffness(random), norm = std::hypot(dx, dy);
    const double e[2] = {dx / norm, dy / norm};
    const bool inside = x + dx >= 0 && x + dx < lx && y + dy >= 0 && y + dy < ly;
    const std::size_t a = node(x, y), b = inside ? node(x + dx, y + dy) : 0;
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) {
        const double block = k * e[r] * e[c];
        add(2 * a + r, 2 * a + c, block);
        if (!inside) continue;
        add(2 * b + r, 2 * b + c, block);
        add(2 * a + r, 2 * b + c, -block);
        add(2 * b + r, 2 * a + c, -block);
      }
  };
  for (int y = 0; y < ly; ++y)
    for (int x = 0; x < lx; ++x) {
      spring(x, y, 1, 0), spring(x, y, 0, 1), spring(x, y, 1, 1), spring(x, y, 1, -1);
      if (x == 0) spring(x, y, -1, 0);
      if (y == 0) spring(x, y, 0, -1);
    }
  return sparse_from_triplets(n, rows, cols, values);
}

Eigen::MatrixXd dense(const SparseSymmetric& a) {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(a.n), static_cast<Eigen::Index>(a.n));
  for (std::size_t i = 0; i < a.n; ++i)
    for (std::size_t k = a.row_start[i]; k < a.row_start[i + 1]; ++k)
      d(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(a.column[k])) = a.value[k];
  return d;
}

TEST(SparseSymmetric, TripletsAtOnePositionAddAndRowsAreSorted) {
  const SparseSymmetric a = sparse_from_triplets(3, {2, 0, 0, 1, 0, 1, 2}, {2, 1, 0, 0, 0, 1, 2}, {1, 5, 2, 5, 3, 4, 6});
  EXPECT_EQ(a.row_start, (std::vector<std::size_t>{0, 2, 4, 5}));
  EXPECT_EQ(a.column, (std::vector<std::size_t>{0, 1, 0, 1, 2}));
  EXPECT_EQ(a.value, (std::vector<double>{5, 5, 5, 4, 7}));
  const double x[3] = {1, 2, 3};
  double y[3];
  a.multiply(x, y);
  EXPECT_EQ(y[0], 15);
  EXPECT_EQ(y[1], 13);
  EXPECT_EQ(y[2], 21);
}

TEST(SparseSymmetric, RefusesAsymmetryIndicesOutsideAndNonFiniteValues) {
  const auto message = [](auto f) {
    try {
      f();
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([] { sparse_from_triplets(2, {0}, {1}, {1.0}); }).find("not symmetric"), std::string::npos);
  EXPECT_NE(message([] {
              sparse_from_triplets(2, {0, 1}, {1, 0}, {1.0, 1.0 + 1e-16 * 3});
            }).find("not symmetric"),
            std::string::npos);
  EXPECT_NE(message([] { sparse_from_triplets(2, {2}, {0}, {1.0}); }).find("outside"), std::string::npos);
  EXPECT_NE(message([] { sparse_from_triplets(2, {0}, {0}, {NAN}); }).find("not finite"), std::string::npos);
  EXPECT_NE(message([] { sparse_from_triplets(2, {0, 1}, {0}, {1.0}); }).find("matrix"), std::string::npos);
}

/// SLEPc's `count` pairs nearest the middle of the spectrum against the dense solver's: values
/// to 1e-10 relative, and the two sets of vectors span the same space (every principal angle's
/// cosine ≥ 1 − 1e-10).
void expect_nearest_match_dense(const SparseSymmetric& a, int count) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> reference(dense(a));
  const Eigen::VectorXd& all = reference.eigenvalues();
  const Eigen::Index middle = all.size() / 2;
  // The shift between two levels, so that the `count` nearest are one well-defined set.
  const double sigma = 0.5 * (all(middle) + all(middle + 1));
  ShiftInvertConfig config;
  config.count = count;
  const ShiftInvertResult r = slepc_nearest(a, sigma, config);
  ASSERT_EQ(r.values.size(), static_cast<std::size_t>(count));
  std::vector<Eigen::Index> nearest(static_cast<std::size_t>(all.size()));
  for (Eigen::Index i = 0; i < all.size(); ++i) nearest[static_cast<std::size_t>(i)] = i;
  std::sort(nearest.begin(), nearest.end(),
            [&](auto x, auto y) { return std::fabs(all(x) - sigma) < std::fabs(all(y) - sigma); });
  nearest.resize(static_cast<std::size_t>(count));
  std::sort(nearest.begin(), nearest.end());
  Eigen::MatrixXd expected(all.size(), count);
  for (int j = 0; j < count; ++j) {
    const Eigen::Index k = nearest[static_cast<std::size_t>(j)];
    EXPECT_NEAR(r.values[static_cast<std::size_t>(j)], all(k), 1e-10 * std::fabs(all(k))) << j;
    expected.col(j) = reference.eigenvectors().col(k);
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> overlap(expected.transpose() * r.vectors);
  EXPECT_GE(overlap.singularValues().minCoeff(), 1 - 1e-10);
}

/// Spectrum slicing over an interval between levels of the dense spectrum: the same 26 eigenvalues
/// to 1e-10 relative and the same 26-dimensional eigenspace.
void expect_window_matches_dense(const SparseSymmetric& a) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> reference(dense(a));
  const Eigen::VectorXd& all = reference.eigenvalues();
  const Eigen::Index first = all.size() / 3, last = first + 25;
  const double lo = 0.5 * (all(first - 1) + all(first)), hi = 0.5 * (all(last) + all(last + 1));
  const ShiftInvertResult r = slepc_window(a, lo, hi);
  ASSERT_EQ(r.values.size(), 26U);
  for (Eigen::Index j = 0; j < 26; ++j)
    EXPECT_NEAR(r.values[static_cast<std::size_t>(j)], all(first + j), 1e-10 * std::fabs(all(first + j))) << j;
  const Eigen::JacobiSVD<Eigen::MatrixXd> overlap(reference.eigenvectors().middleCols(first, 26).transpose() * r.vectors);
  EXPECT_GE(overlap.singularValues().minCoeff(), 1 - 1e-10);
}

TEST(SlepcSparseWindow, EqualsTheDenseSolverOnARandomNet) {
  if (!have_slepc()) GTEST_SKIP() << "this build has no SLEPc";
  expect_window_matches_dense(sparse_net(24, 25, 7));
  EXPECT_THROW(slepc_window(sparse_net(3, 3, 1), 2.0, 1.0), InvalidInput);
}

TEST(SlepcSparseNearest, EqualsTheDenseSolverOnARandomNet) {
  if (!have_slepc()) GTEST_SKIP() << "this build has no SLEPc";
  expect_nearest_match_dense(sparse_net(24, 25, 7), 12);  // 1200 rows
}

TEST(SlepcSparseNearest, RefusesTooManyPairsAndAnInfiniteShift) {
  if (!have_slepc()) GTEST_SKIP() << "this build has no SLEPc";
  const SparseSymmetric a = sparse_net(3, 3, 1);
  ShiftInvertConfig config;
  config.count = static_cast<int>(a.n);
  EXPECT_THROW(slepc_nearest(a, 1.0, config), InvalidInput);
  config.count = 2;
  EXPECT_THROW(slepc_nearest(a, INFINITY, config), InvalidInput);
}

// Run by SlepcSparseNearest.EqualsTheDenseSolverOnTwoMpiRanks under mpiexec -np 2 (skipped when
// run alone): every rank assembles its own rows and receives every vector, nearest σ and by slicing.
TEST(SlepcSparseNearestOnRanks, Child) {
  if (!std::getenv("GRANULAR_SPARSE_RANK_CHILD")) GTEST_SKIP() << "run by EqualsTheDenseSolverOnTwoMpiRanks";
  expect_nearest_match_dense(sparse_net(24, 25, 7), 12);
  expect_window_matches_dense(sparse_net(24, 25, 7));
}

#ifdef GRANULAR_MPIEXEC_PATH
TEST(SlepcSparseNearest, EqualsTheDenseSolverOnTwoMpiRanks) {
  if (!have_slepc()) GTEST_SKIP() << "this build has no SLEPc";
  // A process that has run SLEPc is an MPI singleton whose OMPI_/PMIX_ variables would confuse
  // the mpiexec it starts: unset them first.
  const std::string command =
      "for v in $(env | sed -n 's/^\\(OMPI_[^=]*\\|PMIX_[^=]*\\)=.*/\\1/p'); do unset $v; done; "
      "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
      "GRANULAR_SPARSE_RANK_CHILD=1 " +
      std::string(GRANULAR_MPIEXEC_PATH) + " --oversubscribe -np 2 " +
      std::filesystem::read_symlink("/proc/self/exe").string() +  // this program
      " --gtest_filter=SlepcSparseNearestOnRanks.Child > /dev/null 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0);
}
#endif

}  // namespace
}  // namespace granular
