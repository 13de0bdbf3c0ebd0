// The dynamics against exact and physical results: the modal solution of the linear chain,
// the active window, ballistic spreading, sonic-vacuum pulses, the kicks, the spectrum.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "dynamics_fixtures.hpp"
#include "granular/analysis/exponent_report.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/observers.hpp"
#include "granular/dynamics/spread.hpp"
#include "granular/error.hpp"
#include "granular/linear/detail/lapack_eigensolver.hpp"
#include "granular/linear/dynamical_matrix.hpp"

namespace granular {
namespace {

using fixtures::relative_difference;

// u(t) = M^{-1/2} Σ_k w_k [ (w_k·M^{1/2}u0) cos ω_k t + (w_k·M^{1/2}v0) sin(ω_k t)/ω_k ] for the
// linear law, from the eigenvectors of the symmetric dynamical matrix (docs/physics.md, "The linear spectrum").
std::vector<double> modal_solution(const Chain& chain, const State& s0, double t) {
  const EigenDecomposition e = LapackEigensolver().solve(dynamical_matrix(chain), true);
  const std::size_t n = chain.size();
  std::vector<double> u(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const double omega = std::sqrt(e.values[static_cast<Eigen::Index>(k)]);
    double a = 0, b = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w = e.vectors(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k));
      a += w * std::sqrt(chain.mass[i]) * s0.u[i];
      b += w * std::sqrt(chain.mass[i]) * s0.v[i];
    }
    const double c = a * std::cos(omega * t) + b * std::sin(omega * t) / omega;
    for (std::size_t i = 0; i < n; ++i)
      u[i] += c * e.vectors(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) / std::sqrt(chain.mass[i]);
  }
  return u;
}

TEST(LinearLaw, ReproducesTheExactModalSolution) {
  for (bool velocity : {false, true}) {
    const Chain chain = fixtures::anderson(101, 10.0);
    const ForceLaw law = make_force_law(ForceLawKind::linear, chain);
    const State s0 = velocity ? velocity_kick(chain, 50, 8e-3) : displacement_kick(chain, 50, 1e-7);
    const double tau = 0.01e-6, duration = 0.5e-3;  // waves reach the walls and reflect: all modes matter
    const auto p = fixtures::run(make_splitting_propagator(law, chain, saba2c(), tau, s0),
                                 static_cast<std::size_t>(std::llround(duration / tau)));
    const double error = relative_difference(p->displacement(), modal_solution(chain, s0, duration));
    std::printf("  %s kick: relative difference %.3e\n", velocity ? "velocity" : "displacement", error);
    EXPECT_LT(error, 1e-9);
  }
}

TEST(ActiveWindow, SameFinalStateAsTheFullChain) {
  for (double f0 : {10.0, 0.0}) {
    const Chain chain = fixtures::anderson(1001, f0);
    const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
    const State s0 = displacement_kick(chain, 500, 1e-7);
    const std::size_t steps = 2000;  // 2 ms at 1 µs: the front covers a fraction of the chain
    const auto on = fixtures::run(make_splitting_propagator(law, chain, saba2c(), 1e-6, s0, {true}), steps);
    const auto off = fixtures::run(make_splitting_propagator(law, chain, saba2c(), 1e-6, s0, {false}), steps);
    const double du = relative_difference(on->displacement(), off->displacement());
    const double dv = relative_difference(on->velocity(), off->velocity());
    std::printf("  F0 = %g: window [%zu, %zu) of %zu, bond updates %.3g vs %.3g, difference u %.2e v %.2e\n", f0,
                on->window_begin(), on->window_end(), chain.size(), static_cast<double>(on->bond_updates()),
                static_cast<double>(off->bond_updates()), du, dv);
    EXPECT_LT(du, 1e-12);
    EXPECT_LT(dv, 1e-12);
    EXPECT_LT(on->bond_updates(), off->bond_updates()) << "the window saved no work";
  }
}

TEST(Spreading, HomogeneousPrecompressedChainIsBallistic) {
  const Chain chain = fixtures::homogeneous(1401, 10.0);  // Ω T ≈ 1137 < N: no wall in 10 ms
  EnergySpreadObserver r({.dense = {4e-3, 1e-2, 1e-5}});  // the study's fit grid
  spread(chain, displacement_kick(chain, centre_site(1401), 1e-7), {}, r);
  const ExponentReport fit = report_exponent(r.t, r.m2, 4e-3, 1e-2, {});
  std::printf("  gamma = %.4f ± %.4f, max |L_d − gamma| = %.3f, wall energy %.2e\n", fit.fit.value, fit.fit.error,
              fit.verdict.worst_deviation, r.wall_energy);
  EXPECT_NEAR(fit.fit.value, 2.0, 0.05);
  EXPECT_TRUE(fit.verdict.power_law);
  EXPECT_FALSE(r.reached_walls());
}

TEST(Spreading, SonicVacuumSplitsAKickIntoTwoPulses) {
  const std::size_t n = 801, centre = centre_site(n);
  const Chain chain = fixtures::homogeneous(n, 0.0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  EnergySpreadObserver energy;
  FinalStateObserver final_state;
  spread(chain, displacement_kick(chain, centre, 1e-7), {.duration = 4e-3}, energy, final_state);
  // Two lumps moving apart: most energy far from the kicked bead on both sides.
  double left = 0, right = 0, middle = 0;
  std::size_t peak_left = 0, peak_right = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double e = final_state.energy[i];
    if (i + 20 < centre) {
      left += e;
      if (e > final_state.energy[peak_left]) peak_left = i;
    } else if (i > centre + 20) {
      right += e;
      if (e > final_state.energy[peak_right] || peak_right == 0) peak_right = i;
    } else {
      middle += e;
    }
  }
  const double total = left + right + middle;
  // P⁻¹ stops decaying: compact pulses keep their shape (a linear chain's would keep falling).
  const double ipr_half =
      energy.ipr[static_cast<std::size_t>(std::lower_bound(energy.t.begin(), energy.t.end(), 2e-3) - energy.t.begin())];
  const double ipr_end = energy.ipr.back();
  std::printf("  energy left %.3f right %.3f middle %.3f; peaks at %zu and %zu; P^-1 %.4f at 2 ms, %.4f at 4 ms\n",
              left / total, right / total, middle / total, peak_left, peak_right, ipr_half, ipr_end);
  EXPECT_GT(left / total, 0.1);
  EXPECT_GT(right / total, 0.1);
  EXPECT_LT(middle / total, 0.2);
  EXPECT_GT(centre - peak_left, 50u);
  EXPECT_GT(peak_right - centre, 50u);
  EXPECT_GT(ipr_end, 0.8 * ipr_half);
  EXPECT_GT(ipr_end, 0.05);  // a few beads carry the energy, not hundreds
  (void)law;
}

TEST(InitialConditions, MatchedVelocityIsTheSpecValue) {
  const Chain chain = fixtures::homogeneous(101, 10.0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const double beta = matched_velocity(law, chain, 50, 1e-7);
  EXPECT_NEAR(beta, 8.0359e-3, 0.00005e-3);  // docs/physics.md, "Nonlinear dynamics"
  // Same energy on both kicks, by construction and by measurement.
  EXPECT_NEAR(total_energy(law, chain, velocity_kick(chain, 50, beta)),
              total_energy(law, chain, displacement_kick(chain, 50, 1e-7)), 1e-12 * beta * beta);
}

TEST(InitialConditions, RejectsBadKicks) {
  const Chain chain = fixtures::homogeneous(11, 10.0);
  EXPECT_THROW(displacement_kick(chain, 11, 1e-7), InvalidInput);
  EXPECT_THROW(displacement_kick(chain, 5, 0.0), InvalidInput);
  EXPECT_THROW(displacement_kick(chain, 5, 5e-3), InvalidInput);  // past the bead radius 4.76 mm
  EXPECT_THROW(velocity_kick(chain, 5, std::nan("")), InvalidInput);
  EXPECT_THROW(make_force_law(ForceLawKind::fpu, fixtures::homogeneous(11, 0.0)), InvalidInput);
}

TEST(ForceLaw, HertzForceStiffnessAndPotentialAreConsistent) {
  for (double f0 : {10.0, 0.1, 0.0}) {
    const Chain chain = fixtures::anderson(5, f0);
    for (ForceLawKind kind : {ForceLawKind::hertz, ForceLawKind::fpu, ForceLawKind::linear}) {
      if (f0 == 0 && kind != ForceLawKind::hertz) continue;
      const ForceLaw law = make_force_law(kind, chain);
      std::visit(
          [&](const auto& l) {
            for (std::size_t k = 0; k < l.bonds(); ++k) {
              EXPECT_EQ(l.force(k, 0.0), 0.0);  // exact equilibrium
              EXPECT_EQ(l.potential(k, 0.0), 0.0);
              EXPECT_NEAR(l.contact_force(k, 0.0), f0, 1e-12 * f0);
              for (double x : {-3e-7, -1e-8, 2e-8, 1e-7}) {
                const double h = 1e-11;  // central differences of φ and f
                const double df = (l.potential(k, x + h) - l.potential(k, x - h)) / (2 * h);
                const double ds = (l.force(k, x + h) - l.force(k, x - h)) / (2 * h);
                EXPECT_NEAR(df, l.force(k, x), 1e-6 * std::abs(l.force(k, x)) + 1e-9) << "k " << k << " x " << x;
                EXPECT_NEAR(ds, l.stiffness(k, x), 1e-5 * std::abs(l.stiffness(k, x)) + 1e-3) << "k " << k << " x " << x;
              }
            }
          },
          law);
    }
  }
  // FPU is Hertz's Taylor expansion to x³: the difference is the x⁴ term, (3/128) A Δ^{-5/2} x⁴.
  const Chain chain = fixtures::homogeneous(5, 10.0);
  const HertzLaw hertz(chain);
  const PolynomialLaw fpu(chain, 3);
  const double delta = chain.overlap[2];
  for (double x : {1e-8, -2e-8}) {
    const double fourth = 3.0 / 128 * chain.contact[2] * std::pow(delta, -2.5) * std::pow(x, 4);
    EXPECT_NEAR(hertz.force(2, x) - fpu.force(2, x), fourth, 0.05 * fourth) << x;
  }
}

TEST(SpectralDensity, PeaksAtTheFrequencyOfAnExcitedMode) {
  const Chain chain = fixtures::anderson(60, 10.0);
  const EigenDecomposition e = LapackEigensolver().solve(dynamical_matrix(chain), true);
  const std::size_t mode = 20;
  State s0(chain.size());
  for (std::size_t i = 0; i < chain.size(); ++i)
    s0.u[i] = 1e-8 * e.vectors(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(mode)) / std::sqrt(chain.mass[i]);
  const IntegrationConfig config{.duration = 5e-3, .force_law = ForceLawKind::linear};
  const auto run = [&](SpectrumSource source) {
    EnergySpreadObserver energy;
    SpectralDensityObserver g({.samples = 2001, .source = source});
    spread(chain, s0, config, energy, g);
    return g;
  };
  const SpectralDensityObserver r = run(SpectrumSource::displacement);
  const std::size_t peak =
      static_cast<std::size_t>(std::max_element(r.density.begin(), r.density.end()) - r.density.begin());
  const double expected = frequency_khz(e.values[static_cast<Eigen::Index>(mode)]);
  const double resolution = r.freq_khz[1];
  std::printf("  peak %.4f kHz, mode %.4f kHz, resolution %.4f kHz\n", r.freq_khz[peak], expected, resolution);
  EXPECT_NEAR(r.freq_khz[peak], expected, resolution);
  EXPECT_DOUBLE_EQ(r.density[peak], 1.0);
  // The velocities of a single mode oscillate at the same frequency.
  const SpectralDensityObserver v = run(SpectrumSource::velocity);
  const auto v_peak = std::max_element(v.density.begin(), v.density.end()) - v.density.begin();
  EXPECT_NEAR(v.freq_khz[static_cast<std::size_t>(v_peak)], expected, resolution);
}

TEST(SpectralDensity, VelocitySpectrumShowsTheModesAPermanentStepBuries) {
  // A velocity kick gives the chain momentum: every bead the wave has passed keeps a displacement,
  // a step in u_n(t), whose power ∝ 1/ν² puts g's maximum at 0 Hz (and in the sonic vacuum hides
  // everything else). The velocity is the step's derivative: a pulse, white, and above it the
  // chain's vibrations — at F0 = 10 N the localized modes — stand out.
  const std::size_t n = 401;
  for (double f0 : {10.0, 0.0}) {
    const Chain chain = fixtures::anderson(n, f0);
    const State kick = velocity_kick(chain, centre_site(n), 8e-3);
    const auto run = [&](SpectrumSource source) {
      EnergySpreadObserver energy({.samples = 10});
      SpectralDensityObserver g({.samples = 801, .source = source});  // every 2.5 µs: up to 200 kHz
      spread(chain, kick, {.duration = 2e-3}, energy, g);
      return g;
    };
    const SpectralDensityObserver u = run(SpectrumSource::displacement), v = run(SpectrumSource::velocity);
    const auto argmax = [](const std::vector<double>& g) {
      return static_cast<std::size_t>(std::max_element(g.begin(), g.end()) - g.begin());
    };
    const std::size_t at5 = static_cast<std::size_t>(std::lround(5.0 / u.freq_khz[1]));  // bin of 5 kHz
    std::printf("  F0 = %g N: displacement peak %.2f kHz, velocity peak %.2f kHz; g(5 kHz) %.2e vs %.2e\n", f0,
                u.freq_khz[argmax(u.density)], v.freq_khz[argmax(v.density)], u.density[at5], v.density[at5]);
    EXPECT_EQ(argmax(u.density), 0u);
    EXPECT_GT(v.density[at5], 10 * u.density[at5]);  // measured 24× (10 N) and 48× (0 N)
    if (f0 > 0) {
      EXPECT_GT(v.freq_khz[argmax(v.density)], 5.0) << "a mode, not the step";
    }
  }
}

}  // namespace
}  // namespace granular
