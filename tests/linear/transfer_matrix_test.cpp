// Transfer-matrix Lyapunov exponents against exact results for periodic chains (docs/physics.md, "The linear spectrum",
// "Infinite chains"), and the determinism the kernel promises.
//
// Periodic chains are given by a test source whose wall bonds equal the bulk bonds (walls made
// of fixed beads): then (u_{N+1}, u_N) = T_cell^{N/L} (1, 0) exactly, and both the finite-N value
// and the N → ∞ limit have closed forms. With flat walls the first and last bonds differ; that
// changes only the starting vector, i.e. λ by O(1/N) (checked below), not the limit.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "fixtures.hpp"
#include "granular/error.hpp"
#include "granular/linear/band_edges.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/transfer_matrix.hpp"

namespace granular {
namespace {

/// N beads repeating the masses `cell`, every bond (walls included) of stiffness `b`.
class PeriodicBeads final : public BeadSource {
 public:
  PeriodicBeads(std::vector<double> cell, double b, std::size_t n) : cell_(std::move(cell)), b_(b), n_(n) {}
  std::size_t size() const override { return n_; }
  void read(std::size_t first, std::size_t count, double* mass, double* stiffness) const override {
    for (std::size_t i = 0; i < count; ++i) mass[i] = cell_[(first + i) % cell_.size()];
    for (std::size_t i = 0; i <= count; ++i) stiffness[i] = b_;
  }

 private:
  std::vector<double> cell_;
  double b_;
  std::size_t n_;
};

using Matrix2 = std::array<double, 4>;  // row-major 2 × 2

Matrix2 multiply(const Matrix2& a, const Matrix2& b) {
  return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3]};
}

/// Transfer matrix of a unit cell of masses `cell` between bonds of stiffness b: the product of
/// the one-bead matrices [[2 − m ω²/b, −1], [1, 0]], first bead rightmost.
Matrix2 cell_matrix(const std::vector<double>& cell, double b, double omega2) {
  Matrix2 t{1, 0, 0, 1};
  for (double m : cell) t = multiply({2 - m * omega2 / b, -1, 1, 0}, t);
  return t;
}

/// For det T = 1 and |Tr T| > 2 (eigenvalues s e^{±θ}): ln ‖T^K (1, 0)‖ = Kθ + ln ‖(T − s e^{−θ}) (1, 0)‖
/// − ln(2 sinh θ), up to O(e^{−2Kθ}). Returns θ and that log-norm for K cells.
std::pair<double, double> growing_log_norm(const Matrix2& t, double cells) {
  const double half_trace = (t[0] + t[3]) / 2, s = half_trace > 0 ? 1 : -1;
  const double theta = std::acosh(std::fabs(half_trace));
  const double x = t[0] - s * std::exp(-theta), y = t[2];
  return {theta, cells * theta + 0.5 * std::log(x * x + y * y) - std::log(2 * std::sinh(theta))};
}

double omega2_of(double f_khz) { return std::pow(2 * std::numbers::pi * 1e3 * f_khz, 2); }

struct Bulk {
  double m1, m2, b11, b12;
};
Bulk bulk(double xi = 0.5) {
  const Chain pair = make_chain({fixtures::r1, xi * fixtures::r1}, 10.0);
  const Chain same = make_chain({fixtures::r1, fixtures::r1}, 10.0);
  return {pair.mass[0], pair.mass[1], linear_stiffness(same.contact[1], 10.0), linear_stiffness(pair.contact[1], 10.0)};
}

TEST(TransferMatrix, HomogeneousChainIsExact) {
  const Bulk c = bulk();
  const std::size_t n = 1000000;
  const PeriodicBeads chain({c.m1}, c.b11, n);
  const double f1 = std::sqrt(4 * c.b11 / c.m1) / (2 * std::numbers::pi) * 1e-3;  // band top [kHz]
  const std::vector<double> inside{1, 5, 10, 15, 17.5, 18.0}, above{18.5, 20, 25, 30, 40, 60};
  std::vector<double> f = inside;
  f.insert(f.end(), above.begin(), above.end());
  const TransferMatrixScan scan = transfer_matrix_scan(chain, f);
  int limit_checks = 0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    const double r = c.m1 * omega2_of(f[k]) / c.b11;  // m ω² / B
    if (f[k] < f1) {
      // u_n = sin(n k)/sin k with 2 cos k = 2 − mω²/B: bounded, so λ = 0 up to ln‖·‖/N.
      const double q = std::acos(1 - r / 2);
      const double exact =
          0.5 * std::log(std::pow(std::sin((n + 1) * q), 2) + std::pow(std::sin(n * q), 2)) - std::log(std::sin(q));
      EXPECT_NEAR(scan.lyapunov[k] * n, exact, 1e-6) << f[k] << " kHz";
      EXPECT_LT(std::fabs(scan.lyapunov[k]), 1e-5) << f[k] << " kHz";
    } else {
      // 2 cosh λ = mω²/B − 2 in the limit; the finite chain adds a known O(1/N) constant.
      const double lambda = std::acosh(r / 2 - 1);
      const auto [theta, log_norm] = growing_log_norm(cell_matrix({c.m1}, c.b11, omega2_of(f[k])), double(n));
      EXPECT_NEAR(theta, lambda, 1e-12 * lambda);
      EXPECT_NEAR(scan.lyapunov[k], log_norm / n, 1e-10 * lambda) << f[k] << " kHz";
      if (std::fabs(log_norm / n - lambda) < 1e-7 * lambda) {  // the 1/N term is small enough here
        EXPECT_NEAR(scan.lyapunov[k], lambda, 1e-6 * lambda) << f[k] << " kHz";
        ++limit_checks;
      }
      EXPECT_GT(scan.lyapunov[k], 10 * scan.lyapunov_error[k]) << f[k] << " kHz";
    }
  }
  EXPECT_GE(limit_checks, 4);
}

TEST(TransferMatrix, PeriodicSourceIsTheChainWithBulkWalls) {
  // The test source above and a real Chain (walls = fixed type-1 beads) give the same bits.
  const Bulk c = bulk();
  const std::vector<double> f{3, 12, 18.5, 30};
  const auto from_chain = transfer_matrix_scan(*chain_beads(fixtures::homogeneous_bulk_walls(5000)), f);
  const auto periodic = transfer_matrix_scan(PeriodicBeads({c.m1}, c.b11, 5000), f);
  EXPECT_EQ(from_chain.lyapunov, periodic.lyapunov);
  EXPECT_EQ(from_chain.modes_below, periodic.modes_below);
}

TEST(TransferMatrix, FlatWallsChangeLambdaOnlyByOneOverN) {
  // Flat walls (stiffer end bonds) change the starting vector, not the growth rate: the shift of λ
  // times N is the same constant at N = 1e4 and 1e5 (O(1/N) in λ, not O(1) or O(1/√N)).
  const std::vector<double> f{20, 30};
  std::vector<std::vector<double>> shifts;
  for (std::size_t n : {10000u, 100000u}) {
    const auto flat =
        transfer_matrix_scan(*random_beads(Disorder::homogeneous, {.N = n, .q = 0.5, .seed = 1, .realization = 0}), f);
    const auto bulk_walls = transfer_matrix_scan(*chain_beads(fixtures::homogeneous_bulk_walls(n)), f);
    shifts.emplace_back();
    for (std::size_t k = 0; k < f.size(); ++k) {
      const double shift = (flat.lyapunov[k] - bulk_walls.lyapunov[k]) * double(n);  // an N-independent constant
      EXPECT_GT(std::fabs(shift), 1e-3);
      EXPECT_LT(std::fabs(shift), 2.0);
      shifts.back().push_back(shift);
    }
  }
  for (std::size_t k = 0; k < f.size(); ++k) {
    std::printf("  f = %g kHz: N (lambda_flat - lambda_bulk) = %.6f at N = 1e4, %.6f at 1e5\n", f[k], shifts[0][k],
                shifts[1][k]);
    EXPECT_NEAR(shifts[1][k], shifts[0][k], 1e-3 * std::fabs(shifts[0][k])) << f[k] << " kHz";
  }
}

TEST(TransferMatrix, DiatomicChainMatchesTheUnitCell) {
  const Bulk c = bulk();
  const BandEdges e = band_edges(steel, fixtures::r1, 0.5, 10.0);
  const double fb1 = e.fb1 * 1e-3, fb2 = e.fb2 * 1e-3, fb3 = e.fb3 * 1e-3;
  const std::size_t n = 1000000;
  const std::vector<double> cell{c.m1, c.m2};
  const PeriodicBeads chain(cell, c.b12, n);
  // acoustic band, gap, optical band, above; the band edges themselves ± 0.01 kHz
  const std::vector<double> f{2,          8,    11.5, fb1 - 0.01, fb1 + 0.01, 13, 20, 30, fb2 - 0.01,
                              fb2 + 0.01, 34.5, 35.5, fb3 - 0.01, fb3 + 0.01, 37, 40, 50};
  const TransferMatrixScan scan = transfer_matrix_scan(chain, f);
  int gap = 0, bands = 0, limit_checks = 0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    const Matrix2 t = cell_matrix(cell, c.b12, omega2_of(f[k]));
    const double half_trace = std::fabs(t[0] + t[3]) / 2;
    const bool in_band = f[k] < fb1 || (f[k] > fb2 && f[k] < fb3);
    ASSERT_EQ(half_trace <= 1, in_band) << f[k] << " kHz: the SPEC band edges and the unit cell disagree";
    if (in_band) {
      EXPECT_LT(std::fabs(scan.lyapunov[k]), 1e-4) << f[k] << " kHz";  // bounded: ln‖·‖/N, ‖·‖ ≲ 1/|sin(cell phase)|
      ++bands;
    } else {
      // cosh(λ L_cell) = |Tr T_cell|/2, L_cell = 2 beads
      const double lambda = std::acosh(half_trace) / 2;
      const auto [theta, log_norm] = growing_log_norm(t, double(n / 2));
      EXPECT_NEAR(scan.lyapunov[k], log_norm / n, 1e-10 * lambda) << f[k] << " kHz";
      EXPECT_GT(scan.lyapunov[k], 10 * scan.lyapunov_error[k]) << f[k] << " kHz";
      if (std::fabs(log_norm / n - lambda) < 5e-7 * lambda) {  // where the 1/N term allows (20, 40, 50 kHz)
        EXPECT_NEAR(scan.lyapunov[k], lambda, 1e-6 * lambda) << f[k] << " kHz";
        ++limit_checks;
      }
      ++gap;
    }
  }
  EXPECT_EQ(bands, 8);
  EXPECT_EQ(gap, 9);
  EXPECT_GE(limit_checks, 3);
}

TEST(TransferMatrix, BitIdenticalForAnyThreadCountAndBlock) {
  const auto chain = random_beads(Disorder::rdm2, {.N = 200001, .q = 0.3, .seed = 4, .realization = 2});
  std::vector<double> f;
  for (int k = 0; k <= 150; ++k) f.push_back(0.33 * k);
  TransferMatrixConfig one, two, three;
  one.threads = 1;
  two.threads = 2;
  three.threads = 3;
  const auto a = transfer_matrix_scan(*chain, f, one), b = transfer_matrix_scan(*chain, f, two),
             c = transfer_matrix_scan(*chain, f, three);
  EXPECT_EQ(a.lyapunov, b.lyapunov);
  EXPECT_EQ(a.lyapunov, c.lyapunov);
  EXPECT_EQ(a.lyapunov_error, b.lyapunov_error);
  EXPECT_EQ(a.lyapunov_error, c.lyapunov_error);
  EXPECT_EQ(a.modes_below, b.modes_below);
  EXPECT_EQ(a.modes_below, c.modes_below);
  // a lone frequency (another lane width, padded lanes) gives its own bits too
  const auto lone = transfer_matrix_scan(*chain, {f[77]}, one);
  EXPECT_EQ(lone.lyapunov[0], a.lyapunov[77]);
  EXPECT_EQ(lone.modes_below[0], a.modes_below[77]);
}

TEST(TransferMatrix, ErrorShrinksLikeOneOverRootN) {
  // Anderson chain at 15 kHz (ℓ of a few beads): the segment error falls ~ N^{-1/2}, and chains
  // of other realizations agree with each other within a few errors.
  const std::vector<double> f{15};
  const auto small =
      transfer_matrix_scan(*random_beads(Disorder::anderson, {.N = 100000, .q = 0.5, .seed = 1, .realization = 0}), f);
  const auto large =
      transfer_matrix_scan(*random_beads(Disorder::anderson, {.N = 1600000, .q = 0.5, .seed = 1, .realization = 0}), f);
  const auto other =
      transfer_matrix_scan(*random_beads(Disorder::anderson, {.N = 1600000, .q = 0.5, .seed = 1, .realization = 1}), f);
  EXPECT_NEAR(small.lyapunov_error[0] / large.lyapunov_error[0], 4.0, 1.2);
  const double combined = std::hypot(large.lyapunov_error[0], other.lyapunov_error[0]);
  EXPECT_LT(std::fabs(large.lyapunov[0] - other.lyapunov[0]), 4 * combined);
  EXPECT_GT(large.lyapunov[0], 100 * large.lyapunov_error[0]);
}

TEST(TransferMatrix, RejectsBadParameters) {
  const auto chain = random_beads(Disorder::anderson, {.N = 100, .q = 0.5, .seed = 1, .realization = 0});
  auto message = [&](const std::vector<double>& f, TransferMatrixConfig config) {
    try {
      transfer_matrix_scan(*chain, f, config);
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message({}, {}).find("frequencies"), std::string::npos);
  EXPECT_NE(message({1, -2}, {}).find("frequencies"), std::string::npos);
  EXPECT_NE(message({1, NAN}, {}).find("frequencies"), std::string::npos);
  TransferMatrixConfig one_segment;
  one_segment.segments = 1;
  EXPECT_NE(message({1}, one_segment).find("segments"), std::string::npos);
  // far above any band the recursion overflows: reported, not returned as garbage
  EXPECT_THROW(transfer_matrix_scan(*chain, {1e300}), NumericalError);
}

}  // namespace
}  // namespace granular
