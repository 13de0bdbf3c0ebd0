// The contact-damping flow D_h at fixed positions (damping.hpp): its parity splitting into
// independent two-bead Crank–Nicolson steps against the exact flow v(h) = exp(−h M⁻¹C) v of the
// full bond Laplacian C, computed independently by a symmetric eigendecomposition.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "dynamics_fixtures.hpp"
#include "granular/dynamics/damping.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/scheme.hpp"

namespace granular {
namespace {

// exp(−h M⁻¹C) v = M^{−1/2} exp(−h S) M^{1/2} v, S = M^{−1/2} C M^{−1/2} symmetric;
// C_ii = c_i + c_{i+1}, C_{i,i+1} = −c_{i+1}, c_k = γ A_k [Δ_k + u_{k−1} − u_k]_+^{1/2}, walls at 0.
std::vector<double> exact_contact_damping(const Chain& chain, double gamma, const std::vector<double>& u,
                                          const std::vector<double>& v, double h) {
  const std::size_t n = chain.size();
  std::vector<double> c(n + 1);
  for (std::size_t k = 0; k <= n; ++k) {
    const double x = (k > 0 ? u[k - 1] : 0.0) - (k < n ? u[k] : 0.0);
    c[k] = gamma * chain.contact[k] * std::sqrt(std::max(chain.overlap[k] + x, 0.0));
  }
  const auto idx = [](std::size_t i) { return static_cast<Eigen::Index>(i); };
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(idx(n), idx(n));
  for (std::size_t i = 0; i < n; ++i) {
    s(idx(i), idx(i)) = (c[i] + c[i + 1]) * chain.inverse_mass[i];
    if (i + 1 < n)
      s(idx(i), idx(i + 1)) = s(idx(i + 1), idx(i)) =
          -c[i + 1] * std::sqrt(chain.inverse_mass[i] * chain.inverse_mass[i + 1]);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> e(s);
  Eigen::VectorXd w(idx(n));
  for (std::size_t i = 0; i < n; ++i) w(idx(i)) = std::sqrt(chain.mass[i]) * v[i];
  const Eigen::VectorXd decay = (-h * e.eigenvalues().array()).exp().matrix();
  const Eigen::VectorXd r = e.eigenvectors() * decay.asDiagonal() * (e.eigenvectors().transpose() * w);
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = r(idx(i)) / std::sqrt(chain.mass[i]);
  return out;
}

TEST(DampingFlow, ParitySplitIsSecondOrderAgainstTheExactContactFlow) {
  const Chain chain = fixtures::anderson(31, 0.1);
  // Some bonds stretched open (no damping there), the rest compressed by different amounts.
  std::vector<double> u(chain.size()), v(chain.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    const double x = static_cast<double>(i);
    u[i] = 1.5e-7 * std::sin(0.9 * x);
    v[i] = 1e-2 * std::cos(1.7 * x + 0.3);
  }
  const double gamma = 2e-6;
  DampingFlow flow(chain, {0, gamma});
  double previous = 0;
  for (double h : {8e-6, 4e-6, 2e-6, 1e-6}) {
    const std::vector<double> exact = exact_contact_damping(chain, gamma, u, v, h);
    std::vector<double> w = v;
    const double removed = flow.apply(u, w, h);
    const double error = fixtures::relative_difference(w, exact);
    const double moved = fixtures::relative_difference(v, exact);
    double kinetic_before = 0, kinetic_after = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      kinetic_before += 0.5 * chain.mass[i] * v[i] * v[i];
      kinetic_after += 0.5 * chain.mass[i] * w[i] * w[i];
    }
    std::printf("  h = %g us: |D_h v - exact| / |exact| = %.3e (the flow moved v by %.3e)\n", h * 1e6, error, moved);
    EXPECT_GT(moved, 10 * error);  // the damping does something the comparison can see
    EXPECT_NEAR(removed, kinetic_before - kinetic_after, 1e-12 * kinetic_before);
    EXPECT_GT(removed, 0.0);
    if (previous > 0) {  // local error O(h³): a 2nd-order flow
      EXPECT_GT(previous / error, 7.0) << "h = " << h;
      EXPECT_LT(previous / error, 9.0) << "h = " << h;
    }
    previous = error;
  }
}

TEST(DampingFlow, ConservesMomentumAndLeavesOpenContactsAlone) {
  const Chain chain = fixtures::anderson(12, 0.0);  // F0 = 0: contacts open unless compressed
  std::vector<double> u(chain.size(), 0.0), v(chain.size(), 0.0);
  u[4] = 1e-7;  // bond 4 (beads 3, 4) stretched open, bond 5 (beads 4, 5) compressed
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = 0.01 * static_cast<double>(i % 3) - 0.005;
  DampingFlow flow(chain, {0, 1e-5});
  std::vector<double> w = v;
  double p0 = 0, p1 = 0;
  for (std::size_t i = 0; i < v.size(); ++i) p0 += chain.mass[i] * v[i];
  EXPECT_GT(flow.apply(u, w, 1e-6), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i) p1 += chain.mass[i] * w[i];
  EXPECT_NEAR(p1, p0, 1e-17);  // an interior contact only: momentum kept
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i != 4 && i != 5) {
      EXPECT_EQ(w[i], v[i]) << "bead " << i << " has no closed contact";
    }
  }
  EXPECT_NE(w[4], v[4]);
  EXPECT_NE(w[5], v[5]);
  // The relative velocity of the closed pair decays; it does not change sign at this h.
  EXPECT_LT(std::abs(w[4] - w[5]), std::abs(v[4] - v[5]));
  EXPECT_GT((w[4] - w[5]) * (v[4] - v[5]), 0.0);
}

// The damped propagator runs each step boundary as one blocked pass (the damping substeps of both
// steps, the correctors, the drift) and the kicks through the conservative kernels: it must equal
// the plain composition E_{τ/2} O_{τ/2} Φ_τ O_{τ/2} E_{τ/2} of DampingFlow sweeps and one
// conservative step, to rounding.
// A disturbed state along the whole chain (N = 300: several blocks) with some contacts open.
TEST(DampingFlow, FusedDampedStepsEqualTheStrangCompositionOfTheParts) {
  const Chain chain = fixtures::anderson(300, 0.1);
  State s0(chain.size());
  for (std::size_t i = 0; i < s0.size(); ++i) {
    const double x = static_cast<double>(i);
    s0.u[i] = 4e-8 * std::sin(1.3 * x + 0.2);
    s0.v[i] = 2e-3 * std::cos(0.7 * x);
  }
  const double tau = 0.1e-6;
  const std::size_t steps = 200;  // 20 µs
  for (ForceLawKind kind : {ForceLawKind::hertz, ForceLawKind::fpu})
    for (const SplittingScheme& scheme : {saba2c(), aba864()})
      for (const Damping damping : {Damping{0, 2e-6}, Damping{2e-4, 0}, Damping{2e-4, 2e-6}}) {
        const ForceLaw law = make_force_law(kind, chain);
        DampingFlow flow(chain, damping);
        State s = s0;
        double removed = 0;
        for (std::size_t step = 0; step < steps; ++step) {
          removed += flow.apply(s.u, s.v, tau / 2, DampingFlow::Sweep::even_first);
          auto p = make_splitting_propagator(law, chain, scheme, tau, s, {false});
          p->advance(1);
          s = p->state();
          removed += flow.apply(s.u, s.v, tau / 2, DampingFlow::Sweep::odd_first);
        }
        auto fused = make_damped_propagator(law, chain, scheme, tau, s0, damping);
        fused->advance(steps / 3);
        fused->advance(steps - steps / 3);
        const double du = fixtures::relative_difference(fused->displacement(), s.u);
        const double dv = fixtures::relative_difference(fused->velocity(), s.v);
        const double moved = fixtures::relative_difference(s.v, s0.v);
        std::printf("  %s %s tau_d = %g gamma = %g: fused vs composed u %.1e, v %.1e; dissipated %.6e vs %.6e J\n",
                    to_string(kind).c_str(), scheme.name.c_str(), damping.time, damping.kk_gamma, du, dv,
                    fused->dissipated_energy(), removed);
        EXPECT_GT(moved, 0.1);
        EXPECT_LT(du, 1e-11);
        EXPECT_LT(dv, 1e-11);
        EXPECT_NEAR(fused->dissipated_energy(), removed, 1e-9 * removed);
        EXPECT_GT(removed, 0.0);
      }
}

}  // namespace
}  // namespace granular
