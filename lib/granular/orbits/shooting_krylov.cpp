// Matrix-free Newton–Krylov correction for half-period shooting (detail/shooting_krylov.hpp).
//
// Why a preconditioner: linearized about the precompressed chain, from (x0, 0) the mass-weighted
// modes evolve as cos(ω_k t), so u̇(T/2) = J_lin x0 with J_lin = −M^{-1/2} W diag(ω_k sin(π ω_k/ω_b))
// Wᵀ M^{1/2} (W the unit eigenvectors of D = M^{-1/2} K M^{-1/2}). Its eigenvalues spread over the
// band, so plain GMRES needs ~N iterations. A breather's J differs from J_lin where the breather
// is (a few beads: a perturbation of low rank) and by the scheme's O(τ²): J J_lin⁻¹ is the identity
// plus little more than that low rank, which GMRES resolves in about as many iterations. J_lin⁻¹ is
// applied through W (two N × N products; W costs N² doubles, 8 MB at N = 1000). Right
// preconditioning (GMRES on J J_lin⁻¹ y = −u̇, δ = J_lin⁻¹ y) keeps the tolerance on the true
// residual.
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <unsupported/Eigen/IterativeSolvers>

#include "granular/dynamics/tangent_map.hpp"
#include "granular/error.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/orbits/detail/shooting_krylov.hpp"

namespace granular::detail {
namespace {

// A matrix-free operator for Eigen's GMRES: y = A x by a callback (Eigen's "matrix-free solvers"
// pattern: an EigenBase with a sparse-shaped product).
class ShootingKrylovOperator;

}  // namespace
}  // namespace granular::detail

namespace Eigen::internal {
template <>
struct traits<granular::detail::ShootingKrylovOperator> : public traits<Eigen::SparseMatrix<double>> {};
}  // namespace Eigen::internal

namespace granular::detail {
namespace {

class ShootingKrylovOperator : public Eigen::EigenBase<ShootingKrylovOperator> {
 public:
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic, IsRowMajor = false };

  ShootingKrylovOperator(Eigen::Index n, std::function<Eigen::VectorXd(const Eigen::VectorXd&)> apply)
      : n_(n), apply_(std::move(apply)) {}
  Eigen::Index rows() const { return n_; }
  Eigen::Index cols() const { return n_; }
  template <class Rhs>
  Eigen::Product<ShootingKrylovOperator, Rhs, Eigen::AliasFreeProduct> operator*(const Eigen::MatrixBase<Rhs>& x) const {
    return Eigen::Product<ShootingKrylovOperator, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }
  Eigen::VectorXd apply(const Eigen::VectorXd& x) const { return apply_(x); }

 private:
  Eigen::Index n_;
  std::function<Eigen::VectorXd(const Eigen::VectorXd&)> apply_;
};

}  // namespace
}  // namespace granular::detail

namespace Eigen::internal {
template <class Rhs>
struct generic_product_impl<granular::detail::ShootingKrylovOperator, Rhs, SparseShape, DenseShape, GemvProduct>
    : generic_product_impl_base<granular::detail::ShootingKrylovOperator, Rhs,
                                generic_product_impl<granular::detail::ShootingKrylovOperator, Rhs>> {
  using Scalar = typename Product<granular::detail::ShootingKrylovOperator, Rhs>::Scalar;
  template <class Dest>
  static void scaleAndAddTo(Dest& dst, const granular::detail::ShootingKrylovOperator& lhs, const Rhs& rhs,
                            const Scalar& alpha) {
    dst.noalias() += alpha * lhs.apply(rhs);
  }
};
}  // namespace Eigen::internal

namespace granular::detail {

ShootingKrylov::ShootingKrylov(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                               std::size_t steps_per_period, double omega, bool precondition)
    : law_(law), chain_(chain), scheme_(scheme), steps_(steps_per_period) {
  if (precondition) {
    const DynamicalMatrix d = dynamical_matrix(chain);
    Spectrum modes = spectrum(d, all_modes(), {.vectors = true});
    modes_ = std::move(modes.vectors);
    inverse_sqrt_mass_ = d.inverse_sqrt_mass;
    mode_omega_.resize(modes.omega2.size());
    for (std::size_t k = 0; k < mode_omega_.size(); ++k) mode_omega_[k] = std::sqrt(std::max(modes.omega2[k], 0.0));
  }
  set_frequency(omega);
}

void ShootingKrylov::set_frequency(double omega) {
  tau_ = 2 * std::numbers::pi / omega / static_cast<double>(steps_);
  inverse_gain_.resize(mode_omega_.size());
  for (std::size_t k = 0; k < inverse_gain_.size(); ++k) {
    const double w = mode_omega_[k];
    // A mode at a multiple of ω_b makes J_lin singular; a floor keeps J_lin⁻¹ finite there (J is
    // near-singular in that direction too, so the preconditioned operator stays near 1 there).
    double s = std::sin(std::numbers::pi * w / omega);
    if (std::abs(s) < 1e-6) s = std::copysign(1e-6, s);
    inverse_gain_[k] = -1 / (std::max(w, 1e-6 * omega) * s);
  }
}

std::vector<double> ShootingKrylov::jacobian_times(const std::vector<double>& x, const std::vector<double>& v) const {
  const std::size_t n = x.size();
  if (std::all_of(v.begin(), v.end(), [](double a) { return a == 0; })) return std::vector<double>(n, 0.0);
  State start(n), deviation(n);
  start.u = x;
  deviation.u = v;
  const auto images = propagate_deviations(law_, chain_, scheme_, tau_, steps_ / 2, start, {deviation});
  return images.deviations[0].v;
}

std::vector<double> ShootingKrylov::precondition(const std::vector<double>& y) const {
  if (modes_.empty()) return y;
  const auto n = static_cast<Eigen::Index>(y.size());
  const Eigen::Map<const Eigen::MatrixXd> w(modes_.data(), n, n);
  const Eigen::Map<const Eigen::VectorXd> ism(inverse_sqrt_mass_.data(), n), gain(inverse_gain_.data(), n),
      yv(y.data(), n);
  // M^{1/2} y in the modes, scaled by the inverse gains, back to displacements by M^{-1/2}.
  const Eigen::VectorXd z = (w.transpose() * yv.cwiseQuotient(ism)).cwiseProduct(gain);
  const Eigen::VectorXd out = (w * z).cwiseProduct(ism);
  return {out.data(), out.data() + n};
}

KrylovCorrection ShootingKrylov::solve(const std::vector<double>& x, const std::vector<double>& velocity,
                                       double tolerance, int max_iterations) const {
  const auto n = static_cast<Eigen::Index>(x.size());
  const auto to_std = [](const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); };
  const ShootingKrylovOperator a(n, [&](const Eigen::VectorXd& y) {
    const auto jy = jacobian_times(x, precondition(to_std(y)));
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(jy.data(), n));
  });
  Eigen::GMRES<ShootingKrylovOperator, Eigen::IdentityPreconditioner> gmres;
  gmres.set_restart(max_iterations);
  gmres.setMaxIterations(max_iterations);
  gmres.setTolerance(tolerance);
  gmres.compute(a);
  const Eigen::VectorXd rhs = -Eigen::Map<const Eigen::VectorXd>(velocity.data(), n);
  const Eigen::VectorXd y = gmres.solve(rhs);
  KrylovCorrection out;
  out.step = precondition(to_std(y));
  out.iterations = static_cast<int>(gmres.iterations());
  out.residual = gmres.error();
  return out;
}

KrylovCorrection ShootingKrylov::solve_bordered(const std::vector<double>& x, const BorderedSystem& system,
                                                double tolerance, int max_iterations) const {
  const std::size_t n = x.size();
  const auto m = static_cast<Eigen::Index>(n + 1);
  if (system.column.size() != n || system.tangent_x.size() != n || system.rhs.size() != n + 1)
    throw InvalidInput("guess", ": the bordered system must have N + 1 rows");
  // P⁻¹ on the first N unknowns: the preconditioned shooting rows s J P⁻¹ ≈ 1.
  const auto inner = [&](const Eigen::VectorXd& y) {
    auto v = precondition(std::vector<double>(y.data(), y.data() + n));
    for (double& a : v) a /= system.jacobian_scale;
    return v;
  };
  const ShootingKrylovOperator a(m, [&](const Eigen::VectorXd& y) {
    const auto v = inner(y);
    const auto jv = jacobian_times(x, v);
    Eigen::VectorXd out(m);
    double last = system.tangent_omega * y[m - 1];
    for (std::size_t i = 0; i < n; ++i) {
      out[static_cast<Eigen::Index>(i)] = system.jacobian_scale * jv[i] + system.column[i] * y[m - 1];
      last += system.tangent_x[i] * v[i];
    }
    out[m - 1] = last;
    return out;
  });
  Eigen::GMRES<ShootingKrylovOperator, Eigen::IdentityPreconditioner> gmres;
  gmres.set_restart(max_iterations);
  gmres.setMaxIterations(max_iterations);
  gmres.setTolerance(tolerance);
  gmres.compute(a);
  const Eigen::VectorXd y = gmres.solve(Eigen::Map<const Eigen::VectorXd>(system.rhs.data(), m));
  KrylovCorrection out;
  out.step = inner(y);
  out.step.push_back(y[m - 1]);
  out.iterations = static_cast<int>(gmres.iterations());
  out.residual = gmres.error();
  return out;
}

}  // namespace granular::detail
