#include "granular/linear/tridiagonal_operator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "granular/error.hpp"
#include "granular/linear/detail/lapack.hpp"
#include "granular/linear/detail/sturm_count.hpp"
#include "granular/number_format.hpp"

namespace granular {

std::size_t TridiagonalOperator::count_below(double sigma) const {
  if (t_.size() == 0) return 0;
  long count = 0;
  detail::sturm_counts<1>(t_, detail::sturm_pivot_floor(t_), &sigma, &count);
  return static_cast<std::size_t>(count);
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
