// The contact-damping flow D_h at fixed positions (damping.hpp): its parity splitting into
// independent two-bead exact pair flows against the exact flow v(h) = exp(−h M⁻¹C) v of the
// full bond Laplacian C, computed independently by a symmetric eigendecomposition.
#include <array>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "dynamics_fixtures.hpp"
#include "granular/dynamics/damping.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/model/quasiperiodic.hpp"

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

// One closed contact between two free beads: the flow of its pair is exact for any h, also where
// hλ/2 > 1 (a Crank–Nicolson step (1 − hλ/2)/(1 + hλ/2) would reverse the relative velocity).
TEST(DampingFlow, OnePairTakesItsExactFlowAlsoWhenStiff) {
  Chain chain;
  chain.mass = {2e-3, 1e-3};
  chain.inverse_mass = {500, 1000};
  chain.radius = {4.76e-3, 3.78e-3};
  chain.contact = {0, 7e9, 0};  // the walls exert nothing
  chain.overlap = {0, 1e-6, 0};
  chain.precompression = 0;
  const double gamma = 1e-4;
  const double lambda = gamma * chain.contact[1] * std::sqrt(chain.overlap[1]) * (500 + 1000);
  DampingFlow flow(chain, Damping{0, gamma});
  const std::vector<double> u{0, 0};
  for (double y : {0.1, 2.0, 10.0}) {  // y = hλ/2
    const double h = 2 * y / lambda;
    std::vector<double> v{0.3, -0.1};
    const double p0 = 2e-3 * v[0] + 1e-3 * v[1], g0 = v[0] - v[1];
    flow.apply(u, v, h, DampingFlow::Sweep::even_first);
    const double g = v[0] - v[1];
    EXPECT_GT(g, 0) << "y " << y;
    EXPECT_NEAR(g, g0 * std::exp(-h * lambda), 1e-12 * g0) << "y " << y;
    EXPECT_NEAR(2e-3 * v[0] + 1e-3 * v[1], p0, 1e-16);
  }
}

// Two beads between walls, F0 = 10 N, Kuwabara–Kono damping (contacts stay closed: everything is
// smooth). Reference: RK4 of m ü = Σ bond forces A[δ]^{3/2} + γ A [δ]^{1/2} δ̇ at 1 ns steps. The
// damped splitting (exact pair flows around SABA2C) must converge to it at 2nd order.
TEST(DampingFlow, OneDampedContactConvergesAtSecondOrderToTheReference) {
  const Chain chain = fixtures::homogeneous(2, 10.0);
  const double gamma = 1e-6, duration = 200e-6;  // λ t ≈ 1: strongly damped over the run
  const auto accelerations = [&](const std::array<double, 4>& s) {
    const double u[4] = {0, s[0], s[1], 0}, v[4] = {0, s[2], s[3], 0};
    double f[3];
    for (int k = 0; k < 3; ++k) {
      const double d = std::max(chain.overlap[k] + u[k] - u[k + 1], 0.0), root = std::sqrt(d);
      f[k] = chain.contact[k] * d * root + gamma * chain.contact[k] * root * (v[k] - v[k + 1]);
    }
    return std::array<double, 2>{(f[0] - f[1]) / chain.mass[0], (f[1] - f[2]) / chain.mass[1]};
  };
  std::array<double, 4> ref{0, 0, 5e-3, -1e-3};  // u0, u1, v0, v1
  const double h = 1e-9;
  for (int i = 0; i < static_cast<int>(std::lround(duration / h)); ++i) {
    const auto d = [&](const std::array<double, 4>& s) {
      const auto a = accelerations(s);
      return std::array<double, 4>{s[2], s[3], a[0], a[1]};
    };
    const auto add = [](std::array<double, 4> s, const std::array<double, 4>& k, double c) {
      for (int j = 0; j < 4; ++j) s[j] += c * k[j];
      return s;
    };
    const auto k1 = d(ref), k2 = d(add(ref, k1, h / 2)), k3 = d(add(ref, k2, h / 2)), k4 = d(add(ref, k3, h));
    for (int j = 0; j < 4; ++j) ref[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  }
  State s0(2);
  s0.v = {5e-3, -1e-3};
  std::vector<double> error;
  for (double tau : {1e-6, 0.5e-6, 0.25e-6, 0.125e-6}) {
    auto p = fixtures::run(make_damped_propagator(make_force_law(ForceLawKind::hertz, chain), chain, saba2c(), tau, s0,
                                                  Damping{0, gamma}),
                           static_cast<std::size_t>(std::lround(duration / tau)));
    const double dv = std::hypot(p->velocity()[0] - ref[2], p->velocity()[1] - ref[3]);
    error.push_back(dv / std::hypot(ref[2], ref[3]));
    std::printf("  tau = %.3f us: relative velocity error %.3e\n", tau * 1e6, error.back());
  }
  for (std::size_t i = 1; i < error.size(); ++i) {
    const double order = std::log2(error[i - 1] / error[i]);
    std::printf("  observed order %.3f\n", order);
    EXPECT_GT(order, 1.8);
    EXPECT_LT(order, 2.3);
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
void expect_fused_equals_composed(const Chain& chain) {
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
        std::printf("  %s%s %s tau_d = %g gamma = %g: fused vs composed u %.1e, v %.1e; dissipated %.6e vs %.6e J\n",
                    chain.onsite.empty() ? "" : "S1 ", to_string(kind).c_str(), scheme.name.c_str(), damping.time,
                    damping.kk_gamma, du, dv, fused->dissipated_energy(), removed);
        EXPECT_GT(moved, 0.1);
        EXPECT_LT(du, 1e-11);
        EXPECT_LT(dv, 1e-11);
        EXPECT_NEAR(fused->dissipated_energy(), removed, 1e-9 * removed);
        EXPECT_GT(removed, 0.0);
      }
}

// Also on a chain with on-site springs (the quasiperiodic S1), whose −k u the fused step's
// corrector carries as the conservative kernels do.
TEST(DampingFlow, FusedDampedStepsEqualTheStrangCompositionOfTheParts) {
  const Quasiperiodic s1{.kind = Quasiperiodic::Kind::s1, .modulation = 0.7, .phase = 0.4};
  for (const Chain& chain : {fixtures::anderson(300, 0.1), quasiperiodic_chain(s1, 300, fixtures::r1, 0.1, steel, 0.4)})
    expect_fused_equals_composed(chain);
}

}  // namespace
}  // namespace granular
