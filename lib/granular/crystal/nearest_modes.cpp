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

namespace {

/// max_r Σ_c |D_rc|: every ω² lies below it (Gershgorin).
double gershgorin_bound(const CrystalMatrix& d) {
  double bound = 0;
  for (std::size_t row = 0; row < d.rows(); ++row) {
    double sum = 0;
    for (auto q = d.matrix.row_start[row]; q < d.matrix.row_start[row + 1]; ++q) sum += std::fabs(d.matrix.value[q]);
    bound = std::max(bound, sum);
  }
  return bound;
}

/// max ‖D w − ω² w‖ / max |D_ij| over the pairs of `r`.
double worst_residual(const CrystalMatrix& d, const ShiftInvertResult& r) {
  double scale = 0;
  for (double v : d.matrix.value) scale = std::max(scale, std::fabs(v));
  double worst = 0;
  for (long k = 0; k < r.vectors.cols(); ++k) {
    const double* w = r.vectors.col(k).data();
    for (std::size_t row = 0; row < d.rows(); ++row) {
      double dw = -r.values[static_cast<std::size_t>(k)] * w[row];
      for (auto q = d.matrix.row_start[row]; q < d.matrix.row_start[row + 1]; ++q)
        dw += d.matrix.value[q] * w[d.matrix.column[q]];
      worst = std::max(worst, std::fabs(dw) / scale);
    }
  }
  return worst;
}

/// The pairs of `r` as crystal_spectrum gives modes: frequencies, IPRs, vectors if asked.
CrystalSpectrum spectrum_of(const CrystalMatrix& d, const ShiftInvertResult& r, double residual,
                            const CrystalSpectrumConfig& config) {
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

std::string khz(double hz) { return format_number(std::round(hz) * 1e-3); }

}  // namespace

NearestMethod nearest_method_for(NearestMethod method, std::size_t beads) {
  if (method != NearestMethod::automatic) return method;
  return have_slepc() && beads >= slepc_from_beads ? NearestMethod::slepc : NearestMethod::arpack;
}

CrystalSpectrum crystal_nearest_modes(const CrystalMatrix& d, double near_hz, long count,
                                      const CrystalSpectrumConfig& config, NearestMethod method) {
  if (!std::isfinite(near_hz) || near_hz < 0)
    throw InvalidInput("near", " " + format_number(near_hz) + ": must be finite and >= 0 [Hz]");
  if (count < 1 || count > static_cast<long>(d.rows()) - 1)
    throw InvalidInput("count", " " + std::to_string(count) + ": must be in 1 ... " + std::to_string(d.rows() - 1) +
                                    " (2N - 1) for a shift-invert Krylov method");
  const double sigma = std::pow(2 * std::numbers::pi * near_hz, 2);
  // A shift beyond Gershgorin's bound is a slip (a unit, a digit), and shift-invert would quietly
  // return the top modes as the "nearest".
  if (const double bound = gershgorin_bound(d); sigma > bound)
    throw InvalidInput("near", " " + format_number(near_hz * 1e-3) +
                                   " kHz: above the crystal's spectrum (every mode is below " +
                                   khz(std::sqrt(bound) / (2 * std::numbers::pi)) + " kHz, Gershgorin's bound)");
  const auto residual_of = [&](const ShiftInvertResult& r) { return worst_residual(d, r); };
  ShiftInvertConfig solver;
  solver.count = static_cast<int>(count);
  ShiftInvertResult r;
  double residual = 0;
  if (nearest_method_for(method, d.beads()) == NearestMethod::slepc) {  // MUMPS's LDLᵀ pivots: no second try needed
    r = slepc_nearest(d.matrix, sigma, solver);
    residual = residual_of(r);
  } else {
    r = arpack_ldlt_or_lu(d, sigma, solver, residual_of, residual);
  }
  return spectrum_of(d, r, residual, config);
}

CrystalSpectrum crystal_window_modes(const CrystalMatrix& d, double lo_hz, double hi_hz,
                                     const CrystalSpectrumConfig& config) {
  if (!(std::isfinite(lo_hz) && std::isfinite(hi_hz) && lo_hz >= 0 && lo_hz < hi_hz))
    throw InvalidInput("window", " " + format_number(lo_hz * 1e-3) + ":" + format_number(hi_hz * 1e-3) +
                                     ": needs 0 <= lo < hi [kHz]");
  const double top = std::sqrt(gershgorin_bound(d)) / (2 * std::numbers::pi);
  if (lo_hz > top)
    throw InvalidInput("window", " from " + format_number(lo_hz * 1e-3) + " kHz: above the crystal's spectrum (every " +
                                     "mode is below " + khz(top) + " kHz, Gershgorin's bound)");
  const auto omega2 = [](double hz) { return std::pow(2 * std::numbers::pi * hz, 2); };
  const ShiftInvertResult r = slepc_window(d.matrix, omega2(lo_hz), omega2(hi_hz));
  return spectrum_of(d, r, worst_residual(d, r), config);
}

}  // namespace granular
