#include "granular/linear/sturm_bisection.hpp"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <string>

#include "granular/error.hpp"
#include "granular/linear/lapack.hpp"
#include "granular/linear/tridiagonal_operator.hpp"

namespace granular {

namespace {

double pivot_floor(const SymTridiagonal& t) {
  double max_e2 = 1;
  for (double e : t.off_diagonal) max_e2 = std::max(max_e2, e * e);
  return std::numeric_limits<double>::min() * max_e2;
}

/// L shifts per sweep; the inner loop over lanes is what the compiler vectorizes.
template <int L>
void count_block(const SymTridiagonal& t, double pivmin, const double* shift, long* count) {
  const std::size_t n = t.size();
  const double* a = t.diagonal.data();
  const double* b = t.off_diagonal.data();
  double p[L], s[L], c[L];
  for (int j = 0; j < L; ++j) {
    s[j] = shift[j];
    double q = a[0] - s[j];
    q = std::fabs(q) <= pivmin ? -pivmin : q;  // dstebz's guard: a zero pivot counts as negative
    p[j] = q;
    c[j] = q < 0 ? 1.0 : 0.0;
  }
  for (std::size_t i = 1; i < n; ++i) {
    const double ai = a[i], b2 = b[i - 1] * b[i - 1];
#pragma GCC ivdep
    for (int j = 0; j < L; ++j) {
      double q = (ai - s[j]) - b2 / p[j];
      q = std::fabs(q) <= pivmin ? -pivmin : q;
      p[j] = q;
      c[j] += q < 0 ? 1.0 : 0.0;
    }
  }
  for (int j = 0; j < L; ++j) count[j] = static_cast<long>(c[j]);
}

void count_many(const SymTridiagonal& t, double pivmin, const std::vector<double>& shifts, std::vector<long>& counts) {
  constexpr int L = 32;
  const std::size_t m = shifts.size();
  counts.assign(m, 0);
  for (std::size_t j0 = 0; j0 < m; j0 += L) {
    double s[L];
    long c[L];
    const std::size_t k = std::min<std::size_t>(L, m - j0);
    for (std::size_t j = 0; j < L; ++j) s[j] = shifts[j0 + std::min(j, k - 1)];  // pad with a repeat
    if (k <= 8) {
      count_block<8>(t, pivmin, s, c);
    } else if (k <= 16) {
      count_block<16>(t, pivmin, s, c);
    } else {
      count_block<32>(t, pivmin, s, c);
    }
    for (std::size_t j = 0; j < k; ++j) counts[j0 + j] = c[j];
  }
}

}  // namespace

std::vector<long> count_below_many(const SymTridiagonal& t, const std::vector<double>& shifts) {
  std::vector<long> c;
  count_many(t, pivot_floor(t), shifts, c);
  return c;
}

std::vector<double> bisect_eigenvalues(const SymTridiagonal& t, int first, int last, double relative_width) {
  const int n = static_cast<int>(t.size());
  if (first < 1 || last < first || last > n)
    throw InvalidInput("eigenvalue index range " + std::to_string(first) + ".." + std::to_string(last) +
                       ": must satisfy 1 <= first <= last <= N = " + std::to_string(n));
  const double pivmin = pivot_floor(t);
  auto [glo, ghi] = TridiagonalOperator(t).spectrum_bounds();
  const double pad = 4 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(glo), std::fabs(ghi)) + 2 * pivmin;
  glo -= pad;
  ghi += pad;
  const int m = last - first + 1;
  // Lane j brackets eigenvalue number first + j: count(lo) < first + j <= count(hi).
  std::vector<double> lo(m, glo), hi(m, ghi);
  auto done = [&](int j) {
    return hi[j] - lo[j] <= relative_width * std::max(std::fabs(lo[j]), std::fabs(hi[j])) + 4 * pivmin;
  };
  std::vector<double> shifts;
  std::vector<long> counts;
  for (int pass = 0; pass < 4000; ++pass) {
    shifts.clear();
    // Lanes with the same bracket form a group; its g lanes spread g shifts evenly over it.
    for (int j = 0; j < m;) {
      int k = j;
      while (k + 1 < m && lo[k + 1] == lo[j] && hi[k + 1] == hi[j]) ++k;
      bool any = false;
      for (int r = j; r <= k; ++r) any = any || !done(r);
      if (any) {
        const int g = k - j + 1;
        for (int r = 1; r <= g; ++r) shifts.push_back(lo[j] + (hi[j] - lo[j]) * r / (g + 1));
      }
      j = k + 1;
    }
    if (shifts.empty()) break;
    count_many(t, pivmin, shifts, counts);
    // Every count narrows every bracket: λ_k < s ⇔ count(s) ≥ k.
    for (std::size_t q = 0; q < shifts.size(); ++q) {
      const double s = shifts[q];
      const long c = counts[q];
      for (int j = 0; j < m; ++j) {
        const long k = first + j;
        if (c >= k) hi[j] = std::min(hi[j], s);
        else lo[j] = std::max(lo[j], s);
      }
    }
  }
  std::vector<double> values(m);
  for (int j = 0; j < m; ++j) {
    if (!done(j)) throw NumericalError("bisection did not converge for eigenvalue " + std::to_string(first + j));
    values[j] = 0.5 * (lo[j] + hi[j]);
  }
  return values;
}

Eigen::MatrixXd inverse_iteration(const SymTridiagonal& t, std::vector<double>& values) {
  const std::size_t n = t.size(), m = values.size();
  Eigen::MatrixXd z(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
  if (m == 0) return z;
  const double norm = t.max_abs();
  const double eps = std::numeric_limits<double>::epsilon();
  // Vectors whose eigenvalues are closer than this are made orthogonal explicitly; farther ones
  // already are, to ~eps‖T‖/gap, by the accuracy of each vector.
  const double cluster = 1e-7 * norm;
  ShiftInvertOperator lu;
  std::vector<double> tw(n);
  std::uint64_t seed = 0x2545F4914F6CDD1Dull;
  for (std::size_t j = 0; j < m; ++j) {
    double* x = z.col(static_cast<Eigen::Index>(j)).data();
    for (std::size_t i = 0; i < n; ++i) {  // fixed pseudo-random start (xorshift), reproducible
      seed ^= seed << 13; seed ^= seed >> 7; seed ^= seed << 17;
      x[i] = static_cast<double>(seed >> 11) * 0x1.0p-53 - 0.5;
    }
    lu.factorize(t, values[j]);
    std::size_t first_close = j;
    while (first_close > 0 && values[j] - values[first_close - 1] < cluster) --first_close;
    double residual = std::numeric_limits<double>::infinity();
    for (int it = 0; it < 6 && residual > 64 * eps * norm; ++it) {
      lu.solve(x);
      for (std::size_t k = first_close; k < j; ++k) {  // Gram–Schmidt within the cluster
        const double* y = z.col(static_cast<Eigen::Index>(k)).data();
        double dot = 0;
        for (std::size_t i = 0; i < n; ++i) dot += x[i] * y[i];
        for (std::size_t i = 0; i < n; ++i) x[i] -= dot * y[i];
      }
      double s2 = 0;
      for (std::size_t i = 0; i < n; ++i) s2 += x[i] * x[i];
      const double inv = 1 / std::sqrt(s2);
      for (std::size_t i = 0; i < n; ++i) x[i] *= inv;
      // Rayleigh quotient and residual ‖Tx − ρx‖ of the unit vector.
      t.multiply(x, tw.data());
      double rho = 0;
      for (std::size_t i = 0; i < n; ++i) rho += x[i] * tw[i];
      double r2 = 0;
      for (std::size_t i = 0; i < n; ++i) r2 += (tw[i] - rho * x[i]) * (tw[i] - rho * x[i]);
      residual = std::sqrt(r2);
      if (it > 0 || residual <= 64 * eps * norm) values[j] = rho;
    }
    if (!(residual <= 1e3 * eps * norm))
      throw NumericalError("inverse iteration: eigenvector " + std::to_string(j) + " did not converge (residual " +
                           std::to_string(residual / norm) + " of ||T||)");
  }
  return z;
}

}  // namespace granular
