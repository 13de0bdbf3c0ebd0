#include "granular/linear/detail/cluster_basis.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include "granular/linear/detail/lapack.hpp"

namespace granular::detail {

namespace {

constexpr int cluster_max_solves = 40;  // a solve gains ≥ gap/width; at gap ≈ width, 3× a solve

// Deterministic start vectors in (−1, 1): splitmix64 of the entry's index.
double cluster_start(std::uint64_t index) {
  std::uint64_t z = index + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-52 - 1.0;
}

// Σ a_i b_i with eight partial sums in a fixed order (vectorized, deterministic).
double cluster_dot(const double* __restrict a, const double* __restrict b, std::size_t n) {
  double part[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8)
    for (std::size_t j = 0; j < 8; ++j) part[j] += a[i + j] * b[i + j];
  for (; i < n; ++i) part[0] += a[i] * b[i];
  return ((part[0] + part[1]) + (part[2] + part[3])) + ((part[4] + part[5]) + (part[6] + part[7]));
}

// Modified Gram–Schmidt on the k columns of the column-major n × k z; false if a column vanishes
// (it depended on the others).
bool cluster_orthonormalize(double* z, std::size_t n, std::size_t k) {
  for (std::size_t j = 0; j < k; ++j) {
    double* zj = z + j * n;
    for (std::size_t c = 0; c < j; ++c) {
      const double* zc = z + c * n;
      const double dot = cluster_dot(zc, zj, n);
      for (std::size_t i = 0; i < n; ++i) zj[i] -= dot * zc[i];
    }
    const double norm2 = cluster_dot(zj, zj, n);
    if (!(norm2 > 0) || !std::isfinite(norm2)) return false;
    const double inv = 1.0 / std::sqrt(norm2);
    for (std::size_t i = 0; i < n; ++i) zj[i] *= inv;
  }
  return true;
}

// ‖T Z − Z (Zᵀ T Z)‖_F of the orthonormal columns of z (column-major n × k); tz: n × k scratch.
double cluster_residual(const double* d, const double* e, std::size_t n, const double* z, std::size_t k, double* tz) {
  for (std::size_t j = 0; j < k; ++j) {
    const double* zj = z + j * n;
    double* t = tz + j * n;
    t[0] = d[0] * zj[0] + e[0] * zj[1];
    for (std::size_t i = 1; i + 1 < n; ++i) t[i] = e[i - 1] * zj[i - 1] + d[i] * zj[i] + e[i] * zj[i + 1];
    t[n - 1] = e[n - 2] * zj[n - 2] + d[n - 1] * zj[n - 1];
  }
  for (std::size_t b = 0; b < k; ++b)  // T z_b − Σ_a z_a (z_aᵀ T z_b), in place
    for (std::size_t a = 0; a < k; ++a) {
      const double h = cluster_dot(z + a * n, tz + b * n, n);
      double* t = tz + b * n;
      const double* za = z + a * n;
      for (std::size_t i = 0; i < n; ++i) t[i] -= h * za[i];
    }
  return std::sqrt(cluster_dot(tz, tz, n * k));
}

}  // namespace

bool cluster_basis(const double* d, const double* e, std::size_t n, const double* lambda, std::size_t count,
                   double tolerance, double* z, ClusterWork& w) {
  if (n < 2 || count == 0 || count > n) return false;
  const std::size_t stride = (count + 7) / 8 * 8;  // rows of x padded to whole vectors; pad columns stay 0
  w.dl.assign(e, e + n - 1);
  w.du.assign(e, e + n - 1);
  w.d.resize(n);
  w.du2.resize(n);
  w.pivots.resize(n);
  double norm = 0;
  for (std::size_t i = 0; i < n; ++i)
    norm = std::fmax(norm, std::fabs(d[i]) + (i > 0 ? std::fabs(e[i - 1]) : 0) + (i + 1 < n ? std::fabs(e[i]) : 0));
  const double sigma = 0.5 * (lambda[0] + lambda[count - 1]);
  for (std::size_t i = 0; i < n; ++i) w.d[i] = d[i] - sigma;
  const int ni = static_cast<int>(n);
  int info = 0;
  dgttrf_(&ni, w.dl.data(), w.d.data(), w.du.data(), w.du2.data(), w.pivots.data(), &info);
  if (info < 0) return false;
  const double floor = std::numeric_limits<double>::epsilon() * norm;
  for (std::size_t i = 0; i < n; ++i) {  // σ on an eigenvalue: a zero pivot becomes ε‖T‖
    if (w.d[i] == 0) w.d[i] = floor;
    w.d[i] = 1.0 / w.d[i];  // the solves multiply
  }

  w.x.assign(n * stride, 0.0);
  w.tx.resize(n * count);
  double* x = w.x.data();
  for (std::size_t j = 0; j < count; ++j)
    for (std::size_t i = 0; i < n; ++i) z[j * n + i] = cluster_start(i * count + j);
  if (!cluster_orthonormalize(z, n, count)) return false;

  int extra = -1;  // solves still to do after the residual test passed
  for (int solve = 0; solve < cluster_max_solves; ++solve) {
    for (std::size_t j = 0; j < count; ++j)  // z → rows of x
      for (std::size_t i = 0; i < n; ++i) x[i * stride + j] = z[j * n + i];
    // X ← (T − σI)⁻¹ X: P L U from dgttrf (dgtts2's order of operations), every column at once
    for (std::size_t i = 0; i + 1 < n; ++i) {
      double* xi = x + i * stride;
      double* xn = xi + stride;
      const double l = w.dl[i];
      if (w.pivots[i] == static_cast<int>(i) + 1) {  // no interchange (1-based)
        for (std::size_t j = 0; j < stride; ++j) xn[j] -= l * xi[j];
      } else {
        for (std::size_t j = 0; j < stride; ++j) {
          const double t = xi[j] - l * xn[j];
          xi[j] = xn[j];
          xn[j] = t;
        }
      }
    }
    {
      double* xl = x + (n - 1) * stride;
      for (std::size_t j = 0; j < stride; ++j) xl[j] *= w.d[n - 1];
      double* xm = x + (n - 2) * stride;
      for (std::size_t j = 0; j < stride; ++j) xm[j] = (xm[j] - w.du[n - 2] * xl[j]) * w.d[n - 2];
    }
    for (std::size_t i = n - 2; i-- > 0;) {
      double* xi = x + i * stride;
      const double* x1 = xi + stride;
      const double* x2 = x1 + stride;
      const double u1 = w.du[i], u2 = w.du2[i], inv = w.d[i];
      for (std::size_t j = 0; j < stride; ++j) xi[j] = (xi[j] - u1 * x1[j] - u2 * x2[j]) * inv;
    }
    for (std::size_t j = 0; j < count; ++j)  // rows of x → z
      for (std::size_t i = 0; i < n; ++i) z[j * n + i] = x[i * stride + j];
    // twice is enough (Kahan): the solve's growth can leave columns far from orthogonal
    if (!cluster_orthonormalize(z, n, count) || !cluster_orthonormalize(z, n, count)) return false;
    if (extra < 0) {
      const double residual = cluster_residual(d, e, n, z, count, w.tx.data());
      if (!std::isfinite(residual)) return false;
      // The residual bounds the angle to the subspace only by residual / gap: once it is reached,
      // two more solves (each a factor width/gap) take the rest of the spectrum down to rounding.
      if (residual <= tolerance) extra = 2;
    } else {
      --extra;
    }
    if (extra == 0) return true;
  }
  return false;
}

}  // namespace granular::detail
