#include "granular/crystal/nearest_modes.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "granular/error.hpp"
#include "granular/linear/detail/shift_invert_eigensolvers.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

/// ARPACK on (D − σI)⁻¹ applied by Eigen's sparse LDLᵀ, or, when the modes' residual (by
/// `worst_residual`) is above 1e-9, by a pivoted sparse LU; `residual` gets the residual of the modes returned.
template <class Residual>
ShiftInvertResult arpack_ldlt_or_lu(const CrystalMatrix& d, double sigma, const ShiftInvertConfig& config,
                                    const Residual& worst_residual, double& residual) {
  const int n = static_cast<int>(d.rows());
  // LDLᵀ first: no pivoting, so on the indefinite D − σI a small pivot could spoil the solves. The
  // residuals tell: above 1e-9 of max |D_ij| the modes are solved again on a pivoted LU.
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(d.matrix.value.size() + d.rows());
  for (std::size_t r = 0; r < d.rows(); ++r) {
    for (auto k = d.matrix.row_start[r]; k < d.matrix.row_start[r + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      t.emplace_back(static_cast<int>(r), static_cast<int>(d.matrix.column[kk]), d.matrix.value[kk]);
    }
    t.emplace_back(static_cast<int>(r), static_cast<int>(r), -sigma);
  }
  Eigen::SparseMatrix<double> shifted(n, n);
  shifted.setFromTriplets(t.begin(), t.end());
  auto krylov = [&](const auto& factorization) {
    return arpack_shift_invert(
        n, sigma,
        [&](const double* x, double* y) {
          Eigen::Map<Eigen::VectorXd>(y, n) = factorization.solve(Eigen::Map<const Eigen::VectorXd>(x, n));
        },
        config);
  };
  ShiftInvertResult r;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(shifted);
  if (ldlt.info() == Eigen::Success) {
    try {
      r = krylov(ldlt);
    } catch (const NumericalError&) {
      r = {};  // ARPACK did not converge on these solves: the LU below decides
    }
  }
  residual = r.values.empty() ? std::numeric_limits<double>::infinity() : worst_residual(r);
  if (!(residual <= 1e-9)) {
    shifted.makeCompressed();
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(shifted);
    if (lu.info() != Eigen::Success)
      throw NumericalError("crystal_nearest_modes: D - sigma I is singular at " +
                           format_number(std::sqrt(sigma) / (2 * std::numbers::pi)) + " Hz (a shift on an eigenvalue?)");
    r = krylov(lu);
    residual = worst_residual(r);
  }
  return r;
}

}  // namespace

CrystalSpectrum crystal_nearest_modes(const CrystalMatrix& d, double near_hz, long count,
                                      const CrystalSpectrumConfig& config, NearestMethod method) {
  if (!std::isfinite(near_hz) || near_hz < 0)
    throw InvalidInput("near", " " + format_number(near_hz) + ": must be finite and >= 0 [Hz]");
  if (count < 1 || count > static_cast<long>(d.rows()) - 1)
    throw InvalidInput("count", " " + std::to_string(count) + ": must be in 1 ... " + std::to_string(d.rows() - 1) +
                                    " (2N - 1) for a shift-invert Krylov method");
  const double sigma = std::pow(2 * std::numbers::pi * near_hz, 2);
  // Every ω² lies below Gershgorin's bound max_r Σ_c |D_rc|: a shift beyond it is a slip (a unit,
  // a digit), and shift-invert would quietly return the top modes as the "nearest".
  double gershgorin = 0;
  for (std::size_t row = 0; row < d.rows(); ++row) {
    double sum = 0;
    for (auto q = d.matrix.row_start[row]; q < d.matrix.row_start[row + 1]; ++q) sum += std::fabs(d.matrix.value[q]);
    gershgorin = std::max(gershgorin, sum);
  }
  if (sigma > gershgorin)
    throw InvalidInput("near", " " + format_number(near_hz * 1e-3) +
                                   " kHz: above the crystal's spectrum (every mode is below " +
                                   format_number(std::round(std::sqrt(gershgorin) / (2 * std::numbers::pi)) * 1e-3) +
                                   " kHz, Gershgorin's bound)");
  double scale = 0;
  for (double v : d.matrix.value) scale = std::max(scale, std::fabs(v));
  auto worst_residual = [&](const ShiftInvertResult& r) {
    double worst = 0;
    for (long k = 0; k < r.vectors.cols(); ++k) {
      const double* w = r.vectors.col(k).data();
      for (std::size_t row = 0; row < d.rows(); ++row) {
        double dw = -r.values[static_cast<std::size_t>(k)] * w[row];
        for (auto q = d.matrix.row_start[row]; q < d.matrix.row_start[row + 1]; ++q)
          dw += d.matrix.value[static_cast<std::size_t>(q)] * w[d.matrix.column[static_cast<std::size_t>(q)]];
        worst = std::max(worst, std::fabs(dw) / scale);
      }
    }
    return worst;
  };
  ShiftInvertConfig solver;
  solver.count = static_cast<int>(count);
  ShiftInvertResult r;
  double residual = 0;
  if (method == NearestMethod::slepc) {  // MUMPS's LU pivots: no second try needed
    r = slepc_nearest(d.matrix, sigma, solver);
    residual = worst_residual(r);
  } else {
    r = arpack_ldlt_or_lu(d, sigma, solver, worst_residual, residual);
  }

  CrystalSpectrum out;
  out.beads = d.beads();
  out.omega2 = r.values;
  for (std::size_t k = 0; k < out.omega2.size(); ++k) {
    const double w2 = out.omega2[k];
    out.freq_hz.push_back(std::copysign(std::sqrt(std::fabs(w2)), w2) / (2 * std::numbers::pi));
    out.ipr.push_back(vector_ipr({r.vectors.col(static_cast<long>(k)).data(), d.rows()}, d.inverse_sqrt_mass));
  }
  out.max_residual = residual;
  if (config.vectors) out.vectors.assign(r.vectors.data(), r.vectors.data() + r.vectors.size());
  return out;
}

}  // namespace granular
