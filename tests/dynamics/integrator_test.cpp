// The splitting schemes against the Odeint reference, against each other and against the
// conservation of energy (docs/physics.md, "Nonlinear dynamics").
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "dynamics_fixtures.hpp"
#include "granular/dynamics/observables.hpp"

namespace granular {
namespace {

using fixtures::relative_difference;

using fixtures::steps_for;

TEST(Scheme, CoefficientsSumToOne) {
  for (const SplittingScheme& s : {saba2c(), saba2(), aba864(), srkn14a()}) {
    double drifts = 0, kicks = 0;
    for (double a : s.drift) drifts += a;
    for (double b : s.kick) kicks += b;
    EXPECT_NEAR(drifts, 1.0, 1e-15) << s.name;
    EXPECT_NEAR(kicks, 1.0, 1e-15) << s.name;
    EXPECT_EQ(s.drift.size(), s.kick.size() + 1) << s.name;
    for (std::size_t i = 0; i < s.drift.size(); ++i) EXPECT_EQ(s.drift[i], s.drift[s.drift.size() - 1 - i]) << s.name;
    for (std::size_t i = 0; i < s.kick.size(); ++i) EXPECT_EQ(s.kick[i], s.kick[s.kick.size() - 1 - i]) << s.name;
  }
  EXPECT_EQ(aba864().kick.size(), 7u);
  EXPECT_EQ(srkn14a().kick.size(), 14u);
  EXPECT_EQ(saba2c().force_evaluations_per_step(), 3u);
  // SABA2C's closed forms (docs/physics.md, "Nonlinear dynamics").
  const SplittingScheme s = saba2c();
  EXPECT_NEAR(s.drift[0], 0.5 - std::sqrt(3.0) / 6, 1e-16);
  EXPECT_NEAR(s.drift[1], std::sqrt(3.0) / 3, 1e-16);
  EXPECT_NEAR(s.corrector, (2 - std::sqrt(3.0)) / 24, 1e-17);
}

// Error of each τ against a converged reference on an F0 = 10 N Anderson chain, where contacts
// stay closed and the force is smooth.
struct OrderCase {
  SplittingScheme scheme;
  double ratio;      // expected error ratio per halving: 2^order
  double first_tau;  // largest τ of four
};

void PrintTo(const OrderCase& c, std::ostream* os) { *os << c.scheme.name; }

class Order : public ::testing::TestWithParam<OrderCase> {};

TEST_P(Order, ErrorFallsAsTauToTheOrder) {
  const auto& c = GetParam();
  const Chain chain = fixtures::anderson(101, 10.0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const State s0 = displacement_kick(chain, centre_site(chain.size()), 1e-7);
  const double duration = 1e-3;
  const auto reference = fixtures::run(make_reference_propagator(law, chain, 1e-6, s0, {1e-16, 1e-16, 0}), 1000);
  double previous = 0;
  for (int h = 0; h < 4; ++h) {
    const double tau = c.first_tau / std::pow(2.0, h);
    const auto p =
        fixtures::run(make_splitting_propagator(law, chain, c.scheme, tau, s0, {false}), steps_for(duration, tau));
    const double error = relative_difference(p->displacement(), reference->displacement());
    std::printf("  %s tau = %g us: error %.3e\n", c.scheme.name.c_str(), tau * 1e6, error);
    ASSERT_GT(error, 1e-11) << "error at the reference's level: the halving says nothing";
    if (h > 0) {
      EXPECT_GT(previous / error, 0.75 * c.ratio) << "tau = " << tau;
      EXPECT_LT(previous / error, 1.25 * c.ratio) << "tau = " << tau;
    }
    previous = error;
  }
}

INSTANTIATE_TEST_SUITE_P(Schemes, Order,
                         ::testing::Values(OrderCase{saba2c(), 16, 1e-6},  // 4th order with the corrector
                                           OrderCase{saba2(), 4, 1e-6},    // 2nd without: the sign matters
                                           OrderCase{aba864(), 16, 2e-6}, OrderCase{srkn14a(), 64, 4e-6}),
                         [](const auto& info) { return info.param.scheme.name; });

// Final positions of SABA2C at small τ within 1e-9 of the reference at F0 = 10 N, every disorder, both kicks.
TEST(Long_Reference, AgreesWithSaba2cAtTenNewtons) {
  for (Disorder d : {Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2})
    for (bool velocity : {false, true}) {
      const Chain chain = fixtures::disordered(d, 201, 10.0);
      const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
      const std::size_t site = centre_site(chain.size());
      const State s0 = velocity ? velocity_kick(chain, site, matched_velocity(law, chain, site, 1e-7))
                                : displacement_kick(chain, site, 1e-7);
      const double tau = 0.02e-6, duration = 1e-3;
      const auto ref =
          fixtures::run(make_reference_propagator(law, chain, tau, s0, {1e-16, 1e-16, 0}), steps_for(duration, tau));
      const auto p = fixtures::run(make_splitting_propagator(law, chain, saba2c(), tau, s0), steps_for(duration, tau));
      const double error = relative_difference(p->displacement(), ref->displacement());
      std::printf("  %s %s: %.3e\n", to_string(d).c_str(), velocity ? "velocity" : "displacement", error);
      EXPECT_LT(error, 1e-9) << to_string(d) << (velocity ? " velocity" : " displacement");
    }
}

// F0 ∈ {0.1, 0}: beads separate, the force is only C¹ and every scheme loses order; the
// difference must still shrink with τ and be ≤ 1e-7 at τ = 0.01 µs. The reference is capped at
// the paper's RK step (0.01 µs): its error estimate does not see contacts opening.
void check_nonsmooth(double f0, bool velocity, std::size_t n, double duration, Disorder disorder = Disorder::anderson) {
  const Chain chain = fixtures::disordered(disorder, n, f0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const std::size_t site = centre_site(n);
  const State s0 = velocity ? velocity_kick(chain, site, 8e-3) : displacement_kick(chain, site, 1e-7);
  const auto ref = fixtures::run(make_reference_propagator(law, chain, 1e-6, s0, {1e-15, 1e-15, 0.01e-6}),
                                 steps_for(duration, 1e-6));
  double previous = 1;
  for (double tau : {0.1e-6, 0.04e-6, 0.02e-6, 0.01e-6}) {
    const auto p = fixtures::run(make_splitting_propagator(law, chain, saba2c(), tau, s0), steps_for(duration, tau));
    const double error = relative_difference(p->displacement(), ref->displacement());
    std::printf("  %s F0 = %g %s tau = %g us: %.3e\n", to_string(disorder).c_str(), f0,
                velocity ? "velocity" : "displacement", tau * 1e6, error);
    EXPECT_LT(error, previous) << "tau = " << tau;
    previous = error;
  }
  EXPECT_LE(previous, 1e-7);
}

TEST(Long_Reference, AgreesAtPointOneNewton) { check_nonsmooth(0.1, false, 101, 0.5e-3); }
TEST(Reference, AgreesInSonicVacuum) { check_nonsmooth(0.0, false, 101, 0.5e-3); }
TEST(Long_Reference, NonSmoothEveryDisorderBothKicksN201) {
  for (Disorder d : {Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2})
    for (double f0 : {0.1, 0.0})
      for (bool velocity : {false, true}) check_nonsmooth(f0, velocity, 201, 1e-3, d);
}

// Relative energy error max_t |H(t) − H0| / H0 on `samples` uniform times.
std::vector<double> energy_errors(const Chain& chain, const SplittingScheme& scheme, double tau, double duration,
                                  std::size_t samples, bool velocity) {
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const std::size_t site = centre_site(chain.size());
  const State s0 = velocity ? velocity_kick(chain, site, matched_velocity(law, chain, site, 1e-7))
                            : displacement_kick(chain, site, 1e-7);
  const double h0 = total_energy(law, chain, s0);
  auto p = make_splitting_propagator(law, chain, scheme, tau, s0);
  const std::size_t steps = steps_for(duration, tau);
  std::vector<double> errors;
  for (std::size_t k = 1; k <= samples; ++k) {
    p->advance(steps * k / samples - p->steps_done());
    errors.push_back(std::abs(total_energy(law, chain, p->state()) - h0) / h0);
  }
  return errors;
}

double max_of(const std::vector<double>& v, std::size_t begin, std::size_t end) {
  double m = 0;
  for (std::size_t i = begin; i < end; ++i) m = std::max(m, v[i]);
  return m;
}

// The energy error at τ = 1 µs depends on the realization through the kicked bead: a light
// (type-2) bead puts the energy into the upper band, where the (ωτ)⁴ error is (f2/f1)⁴ ≈ 40×
// larger. Measured here (max over 200 samples of 10 ms, displacement kick): ≈ 3e-7…5e-7 when the
// kicked bead and its neighbours are type 1, ≈ 1e-5…2e-5 when the kicked bead is type 2. The
// SPEC's 1.4e-7 (N = 2501) and 4.0e-7 (N = 201) belong to the first kind, so the ≤ 5e-7 bound is
// checked on the first realization whose three central beads are type 1 (velocity kick, as the
// displacement kick sits right at the bound); the τ⁴ fall on every kind.
std::uint64_t first_heavy_centre(std::size_t n) {
  for (std::uint64_t r = 0;; ++r) {
    const Chain c = fixtures::anderson(n, 10.0, r);
    const std::size_t s = centre_site(n);
    if (c.radius[s - 1] == fixtures::r1 && c.radius[s] == fixtures::r1 && c.radius[s + 1] == fixtures::r1) return r;
  }
}

void check_energy(std::size_t n, std::uint64_t realization, bool velocity, double bound) {
  const Chain chain = fixtures::anderson(n, 10.0, realization);
  const auto coarse = energy_errors(chain, saba2c(), 1e-6, 1e-2, 200, velocity);
  const auto fine = energy_errors(chain, saba2c(), 0.5e-6, 1e-2, 200, velocity);
  const double e1 = max_of(coarse, 0, 200), e2 = max_of(fine, 0, 200);
  std::printf(
      "  N = %zu, realization %llu, %s kick: max energy error %.3e at 1 us, %.3e at 0.5 us (ratio %.1f); "
      "halves %.3e %.3e\n",
      n, static_cast<unsigned long long>(realization), velocity ? "velocity" : "displacement", e1, e2, e1 / e2,
      max_of(coarse, 0, 100), max_of(coarse, 100, 200));
  EXPECT_LE(e1, bound);
  EXPECT_GE(e1 / e2, 12.0);
  // No drift: the second half of the run is no worse than the first (a drifting error would grow).
  EXPECT_LE(max_of(coarse, 100, 200), 1.5 * max_of(coarse, 0, 100));
}

TEST(Energy, BoundedAndFallsAsTauToTheFourthN201) { check_energy(201, first_heavy_centre(201), true, 5e-7); }
TEST(Energy, LightKickedBeadFallsAsTauToTheFourthN201) { check_energy(201, 0, false, 3e-5); }
TEST(Long_Energy, BoundedAndFallsAsTauToTheFourthN2501) {
  check_energy(2501, first_heavy_centre(2501), true, 5e-7);
  check_energy(2501, first_heavy_centre(2501), false, 5e-7);
  check_energy(2501, 0, false, 3e-5);
}

}  // namespace
}  // namespace granular
