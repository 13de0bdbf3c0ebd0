#include "granular/crystal/nearest_modes.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "granular/error.hpp"
#include "granular/linear/detail/shift_invert_eigensolvers.hpp"
#include "granular/number_format.hpp"

namespace granular {

CrystalSpectrum crystal_nearest_modes(const CrystalMatrix& d, double near_hz, long count,
                                      const CrystalSpectrumConfig& config) {
  if (!std::isfinite(near_hz) || near_hz < 0)
    throw InvalidInput("near", " " + format_number(near_hz) + ": must be finite and >= 0 [Hz]");
  if (count < 1 || count > static_cast<long>(d.rows) - 1)
    throw InvalidInput("count", " " + std::to_string(count) + ": must be in 1 ... " + std::to_string(d.rows - 1) +
                                    " (2N - 1) for a shift-invert Krylov method");
  const int n = static_cast<int>(d.rows);
  const double sigma = std::pow(2 * std::numbers::pi * near_hz, 2);
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(d.value.size() + d.rows);
  for (std::size_t r = 0; r < d.rows; ++r) {
    for (auto k = d.row_start[r]; k < d.row_start[r + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      t.emplace_back(static_cast<int>(r), static_cast<int>(d.column[kk]), d.value[kk]);
    }
    t.emplace_back(static_cast<int>(r), static_cast<int>(r), -sigma);
  }
  Eigen::SparseMatrix<double> shifted(n, n);
  shifted.setFromTriplets(t.begin(), t.end());
  // LDLᵀ without pivoting: D − σI is indefinite, but a 2 × 2 block structure with a shift off the
  // spectrum leaves no zero pivot in practice; a failure is reported, not hidden.
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(shifted);
  if (ldlt.info() != Eigen::Success)
    throw NumericalError("crystal_nearest_modes: the LDL^T factorization of D - sigma I failed at " +
                         format_number(near_hz) + " Hz (a shift on an eigenvalue?)");
  ShiftInvertConfig arpack;
  arpack.count = static_cast<int>(count);
  const ShiftInvertResult r = arpack_shift_invert(
      n, sigma,
      [&](const double* x, double* y) {
        Eigen::Map<Eigen::VectorXd>(y, n) = ldlt.solve(Eigen::Map<const Eigen::VectorXd>(x, n));
      },
      arpack);

  CrystalSpectrum out;
  out.beads = d.beads();
  out.omega2 = r.values;
  for (std::size_t k = 0; k < out.omega2.size(); ++k) {
    const double w2 = out.omega2[k];
    out.freq_hz.push_back(std::copysign(std::sqrt(std::fabs(w2)), w2) / (2 * std::numbers::pi));
    out.ipr.push_back(vector_ipr({r.vectors.col(static_cast<long>(k)).data(), d.rows}, d.inverse_sqrt_mass));
  }
  if (config.vectors) out.vectors.assign(r.vectors.data(), r.vectors.data() + r.vectors.size());
  return out;
}

}  // namespace granular
