#include "granular/linear/tridiagonal_operator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "granular/error.hpp"
#include "granular/linear/detail/lapack.hpp"
#include "granular/number_format.hpp"

namespace granular {

std::size_t TridiagonalOperator::count_below(double sigma) const {
  const std::size_t n = t_.size();
  if (n == 0) return 0;
  const auto& a = t_.diagonal;
  const auto& b = t_.off_diagonal;
  double max_e2 = 1;
  for (double e : b) max_e2 = std::max(max_e2, e * e);
  // dstebz's guard: a pivot smaller than this is replaced by -pivmin, so a zero pivot
  // counts as negative and the next division stays finite.
  const double pivmin = std::numeric_limits<double>::min() * max_e2;
  std::size_t count = 0;
  double p = a[0] - sigma;
  if (std::fabs(p) <= pivmin) p = -pivmin;
  count += p < 0;
  for (std::size_t i = 1; i < n; ++i) {
    p = (a[i] - sigma) - b[i - 1] * b[i - 1] / p;
    if (std::fabs(p) <= pivmin) p = -pivmin;
    count += p < 0;
  }
  return count;
}

std::pair<double, double> TridiagonalOperator::spectrum_bounds() const {
  const std::size_t n = t_.size();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < n; ++i) {
    double r = 0;
    if (i > 0) r += std::fabs(t_.off_diagonal[i - 1]);
    if (i + 1 < n) r += std::fabs(t_.off_diagonal[i]);
    lo = std::min(lo, t_.diagonal[i] - r);
    hi = std::max(hi, t_.diagonal[i] + r);
  }
  return {lo, hi};
}

void ShiftInvertOperator::factorize(const SymTridiagonal& t, double sigma) {
  const int n = static_cast<int>(t.size());
  if (n < 1) throw InvalidInput("shift-invert of an empty matrix");
  if (!std::isfinite(sigma)) throw InvalidInput("shift", " " + format_number(sigma) + ": must be finite");
  const double scale = std::max(t.max_abs(), std::fabs(sigma));
  for (int attempt = 0; attempt < 8; ++attempt) {
    dl_.assign(t.off_diagonal.begin(), t.off_diagonal.end());
    du_ = dl_;
    d_.resize(n);
    for (int i = 0; i < n; ++i) d_[i] = t.diagonal[i] - sigma;
    du2_.assign(std::max(n - 2, 1), 0.0);
    ipiv_.resize(n);
    int info = 0;
    dgttrf_(&n, dl_.data(), d_.data(), du_.data(), du2_.data(), ipiv_.data(), &info);
    if (info < 0) throw NumericalError("dgttrf: argument " + std::to_string(-info) + " invalid");
    if (info == 0) {
      sigma_ = sigma;
      return;
    }
    // Exactly singular: σ is an eigenvalue to working precision. Nudge it.
    sigma += 16 * std::numeric_limits<double>::epsilon() * scale * (attempt + 1);
  }
  throw NumericalError("shift-invert: T - sigma I stays singular near sigma = " + format_number(sigma));
}

void ShiftInvertOperator::solve(double* x) const {
  const int n = static_cast<int>(d_.size()), nrhs = 1;
  int info = 0;
  dgttrs_("N", &n, &nrhs, dl_.data(), d_.data(), du_.data(), du2_.data(), ipiv_.data(), x, &n, &info, 1);
  if (info != 0) throw NumericalError("dgttrs: info = " + std::to_string(info));
}

void ShiftInvertOperator::apply(const double* x, double* y) const {
  std::copy(x, x + d_.size(), y);
  solve(y);
}

}  // namespace granular
