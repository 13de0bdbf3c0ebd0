// The operator pieces the partial-spectrum solvers stand on: inertia counts, many-shift counts,
// the shift-invert LU, the LAPACK index-range solve, bisection + inverse iteration.
#include <cmath>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "granular/linear/detail/lapack.hpp"
#include "granular/linear/detail/lapack_eigensolver.hpp"
#include "granular/linear/detail/sturm_bisection.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/tridiagonal_operator.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"

namespace granular {
namespace {

// Plain loop: Eigen's AVX-512 dot trips a GCC 12 false -Wmaybe-uninitialized under -Werror.
double dot(const Eigen::MatrixXd& a, Eigen::Index i, const Eigen::MatrixXd& b, Eigen::Index j) {
  double s = 0;
  for (Eigen::Index r = 0; r < a.rows(); ++r) s += a(r, i) * b(r, j);
  return s;
}

SymTridiagonal anderson_matrix(std::size_t n, std::uint64_t seed = 3) {
  const auto types = realization_configuration(Disorder::anderson, 0.5, n, seed, 0);
  return dynamical_matrix(make_chain(radii_of(types, 4.76e-3, 0.5), 10.0));
}

// LAPACK sizes are ints: one past 2^31 − 1 is refused, and so is a negative one, which is what a
// workspace query returns when LAPACK's own int arithmetic wrapped (dstevd's n² + 4n + 1 at
// n = 46341 comes back as −2147293650), instead of becoming a one-entry workspace.
TEST(LapackEigensolver, SizesPastAnIntAndWrappedSizesAreRefused) {
  EXPECT_EQ(detail::lapack_int(2147483647, "a workspace"), 2147483647);
  EXPECT_THROW(detail::lapack_int(2147483648, "a workspace"), InvalidInput);
  const std::int64_t n = 46341, wrapped = static_cast<std::int32_t>(static_cast<std::uint32_t>(n * n + 4 * n + 1));
  ASSERT_LT(wrapped, 0);
  try {
    detail::lapack_int(wrapped, "dstevd's workspace");
    ADD_FAILURE() << "a wrapped size accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "N");
  }
  EXPECT_FALSE(detail::stevd_workspace_overflows(46338));
  EXPECT_TRUE(detail::stevd_workspace_overflows(46339));  // the message once said N <= 46340
}

// Every mode with eigenvectors above N = 46338 is refused for its 32-bit sizes whichever driver is
// preferred: a failing driver falls back to dstevd (it once was refused only with stevd preferred,
// and otherwise only for memory, on machines that have less).
TEST(LapackEigensolver, VectorsPastTheStevdLimitAreRefusedForEveryDriver) {
  for (LapackDriver driver : {LapackDriver::stevr, LapackDriver::stemr, LapackDriver::steqr, LapackDriver::stevd}) {
    const SpectrumConfig config{.driver = driver, .vectors = true};
    const std::string problem = full_spectrum_problem(46339, config, all_modes());
    EXPECT_NE(problem.find("32-bit"), std::string::npos) << to_string(driver) << ": " << problem;
  }
  EXPECT_EQ(full_spectrum_problem(46339, SpectrumConfig{.driver = LapackDriver::stevr}, all_modes()).find("32-bit"),
            std::string::npos);  // values only: dstevr's 20 N workspace fits
}

TEST(TridiagonalOperator, CountBelowMatchesFullSpectrumMidGaps) {
  const auto t = anderson_matrix(300);
  const auto full = LapackEigensolver().solve(t, false).values;
  const TridiagonalOperator op(t);
  EXPECT_EQ(op.count_below(full[0] * 0.5), 0u);
  EXPECT_EQ(op.count_below(full[299] * 2), 300u);
  std::vector<double> shifts;
  for (int k = 0; k + 1 < 300; k += 7) shifts.push_back(0.5 * (full[k] + full[k + 1]));
  const auto many = count_below_many(t, shifts);
  for (std::size_t i = 0; i < shifts.size(); ++i) {
    EXPECT_EQ(op.count_below(shifts[i]), static_cast<std::size_t>(7 * i + 1));
    EXPECT_EQ(many[i], static_cast<long>(7 * i + 1));  // one sweep, many shifts: the same counts
  }
  const auto [lo, hi] = op.spectrum_bounds();
  EXPECT_LE(lo, full[0]);
  EXPECT_GE(hi, full[299]);
}

TEST(ShiftInvertOperator, SolvesIndefiniteShiftedSystems) {
  const auto t = anderson_matrix(500);
  const auto full = LapackEigensolver().solve(t, false).values;
  for (double sigma : {0.5 * (full[200] + full[201]), full[350] * (1 + 1e-9), full[499] * 1.5}) {
    ShiftInvertOperator op;
    op.factorize(t, sigma);
    std::vector<double> b(500), x(500), tx(500);
    for (int i = 0; i < 500; ++i) b[i] = std::sin(0.1 * i) + 0.3;
    op.apply(b.data(), x.data());
    t.multiply(x.data(), tx.data());
    double err = 0, bn = 0, xn = 0;
    for (int i = 0; i < 500; ++i) {
      err = std::fmax(err, std::fabs(tx[i] - sigma * x[i] - b[i]));
      bn = std::fmax(bn, std::fabs(b[i]));
      xn = std::fmax(xn, std::fabs(x[i]));
    }
    // backward-stable solve: residual ~ ε ‖T − σI‖ ‖x‖
    EXPECT_LE(err, 1e-12 * (t.max_abs() + std::fabs(sigma)) * xn) << "sigma " << sigma;
  }
}

TEST(LapackEigensolver, IndexRangeEqualsRowsOfFullSolve) {
  const auto t = anderson_matrix(400);
  LapackEigensolver solver;
  const auto full = solver.solve(t, true);
  EigenDecomposition part;
  solver.solve_indices(t, 101, 130, true, part);
  ASSERT_EQ(part.values.size(), 30);
  ASSERT_EQ(part.vectors.cols(), 30);
  for (int j = 0; j < 30; ++j) {
    EXPECT_NEAR(part.values[j], full.values[100 + j], 1e-12 * full.values[399]);
    const double overlap = std::fabs(dot(part.vectors, j, full.vectors, 100 + j));
    EXPECT_NEAR(overlap, 1.0, 1e-9) << j;
  }
  EXPECT_THROW(solver.solve_indices(t, 0, 3, false, part), InvalidInput);
  EXPECT_THROW(solver.solve_indices(t, 5, 401, false, part), InvalidInput);
  EXPECT_THROW(solver.solve_indices(t, 6, 5, false, part), InvalidInput);
  solver.solve_window(t, full.values[10] * 1.0000001, full.values[19] * 1.0000001, false, part);
  ASSERT_EQ(part.values.size(), 9);
  EXPECT_NEAR(part.values[0], full.values[11], 1e-12 * full.values[399]);
  solver.solve_window(t, full.values[399] * 2, full.values[399] * 3, true, part);
  EXPECT_EQ(part.values.size(), 0);
}

TEST(SturmBisection, ValuesAndVectorsMatchLapackWithSmallResiduals) {
  const auto t = anderson_matrix(1000);
  const auto full = LapackEigensolver().solve(t, true);
  auto values = bisect_eigenvalues(t, 400, 440, 1e-14);
  ASSERT_EQ(values.size(), 41u);
  for (int j = 0; j < 41; ++j) EXPECT_NEAR(values[j], full.values[399 + j], 1e-13 * full.values[999]);
  const auto z = inverse_iteration(t, values);
  std::vector<double> tz(1000);
  for (int j = 0; j < 41; ++j) {
    t.multiply(z.col(j).data(), tz.data());
    double r = 0;
    for (int i = 0; i < 1000; ++i) r += std::pow(tz[i] - values[j] * z(i, j), 2);
    EXPECT_LE(std::sqrt(r), 1e-13 * t.max_abs());
    for (int k = 0; k < j; ++k) EXPECT_LE(std::fabs(dot(z, j, z, k)), 1e-10) << j << " " << k;
  }
  EXPECT_THROW(bisect_eigenvalues(t, 0, 2, 1e-14), InvalidInput);
}

}  // namespace
}  // namespace granular
