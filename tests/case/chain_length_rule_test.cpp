// The automatic chain length (--N auto): v = ω_max/2 bounds the speed of the energy front, so at the automatic N the
// wall guard never fires, and a 1.5× longer chain gives the same m̃2 to 1e-12, realization by realization, on the linear
// and on the sonic-vacuum side.
#include "granular/case/chain_length_rule.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "granular/case/time_step_rule.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/model/chain.hpp"

namespace granular {
namespace {

TransportCase long_case(Disorder d, double f0, Kick kick, double duration) {
  TransportCase c;
  c.chain.draw().disorder = d;
  c.chain.F0 = f0;
  c.kick = kick;
  c.dynamics.integration.duration = duration;
  c.fit = false;
  c.dynamics.spread.samples = 40;
  c.realizations = 3;
  return c;
}

TransportCase sized(TransportCase c, double factor = 1) {
  const ChainLength length = automatic_chain_length(c);
  c.chain.N = 2 * static_cast<std::size_t>(std::ceil(factor * static_cast<double>(length.n - 1) / 2)) + 1;
  c.site = 0;  // the centre
  c.chain.draw().centred = true;
  validate(c);
  return c;
}

SpreadingResult run(const TransportCase& c, std::uint64_t r) {
  const Chain chain = c.chain.chain(r);
  return run_spreading(chain, kick(c, chain).initial, spreading_config(c));
}

// Homogeneous chain at F0 = 10 N, a tiny kick: the linear sound speed √(K/m) beads/s of the
// bond at rest; v = ω_max/2 must be at least that, and not absurdly more (the kick barely stiffens).
TEST(ChainLengthRule, MaxGroupVelocityIsTheLinearSoundSpeed) {
  TransportCase c = long_case(Disorder::homogeneous, 10, Kick::displacement, 1e-2);
  c.alpha = 1e-12;
  const ChainLength length = automatic_chain_length(c);
  const Chain chain = make_chain(std::vector<double>(3, c.chain.R1), c.chain.F0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const double k = std::visit([&](const auto& l) { return l.stiffness(1, 0.0); }, law);  // at the static strain
  const double sound = std::sqrt(k / chain.mass[1]);
  EXPECT_GE(length.max_group_velocity, sound);
  EXPECT_LE(length.max_group_velocity, sound * 1.01);
  EXPECT_EQ(length.n, 2 * static_cast<std::size_t>(std::ceil(1.1 * length.max_group_velocity * 1e-2) + 50) + 1);
}

// The front (the active window, grown wherever the kinetic energy passes 1e-30 of H0) moves
// slower than v = ω_max/2, and no energy reaches the walls: with and without precompression, both kicks.
TEST(ChainLengthRule, TheWallGuardNeverFiresAtTheAutomaticN) {
  double fastest = 0;  // the front's reach over v T, for the docs
  for (double f0 : {10.0, 0.0})
    for (Kick kick : {Kick::velocity, Kick::displacement})
      for (Disorder d : {Disorder::anderson, Disorder::rdm2}) {
        const TransportCase c = sized(long_case(d, f0, kick, 2e-2));
        const ChainLength length = automatic_chain_length(c);
        for (std::uint64_t r = 0; r < 2; ++r) {
          const SpreadingResult s = run(c, r);
          EXPECT_FALSE(s.reached_walls) << f0 << " " << to_string(kick) << " " << to_string(d);
          EXPECT_EQ(s.wall_energy, 0.0);
          const double reach =
              static_cast<double>(std::max(kicked_bead(c) - s.window_begin, s.window_end - 1 - kicked_bead(c)));
          EXPECT_LT(reach, length.max_group_velocity * c.dynamics.integration.duration) << f0 << " " << to_string(kick);
          fastest = std::max(fastest, reach / (length.max_group_velocity * c.dynamics.integration.duration));
        }
        const TransportSummary summary = run_transport_study(c, {1, "", false, nullptr});
        EXPECT_EQ(summary.reached_walls, 0u);
      }
  std::printf("front reach / (v T): at most %.3f\n", fastest);
}

// The same realizations at N and at 1.5 N: the beads the wave meets are the same (the centred
// draw), so m̃2 agrees to 1e-12 at every sample.
TEST(ChainLengthRule, OneAndAHalfTimesTheLengthGivesTheSameSpread) {
  for (double f0 : {10.0, 0.0})
    for (Disorder d : {Disorder::anderson, Disorder::rdm1}) {
      const TransportCase a = sized(long_case(d, f0, Kick::velocity, 2e-2));
      const TransportCase b = sized(long_case(d, f0, Kick::velocity, 2e-2), 1.5);
      ASSERT_GE(b.chain.N, a.chain.N + (a.chain.N - 1) / 2);
      for (std::uint64_t r = 0; r < 2; ++r) {
        const SpreadingResult x = run(a, r), y = run(b, r);
        ASSERT_EQ(x.m2.size(), y.m2.size());
        for (std::size_t i = 0; i < x.m2.size(); ++i) {
          EXPECT_NEAR(x.m2[i], y.m2[i], 1e-12 * std::fabs(x.m2[i])) << f0 << " " << to_string(d) << " sample " << i;
          EXPECT_NEAR(x.ipr[i], y.ipr[i], 1e-12 * std::fabs(x.ipr[i]));
        }
        EXPECT_GT(x.m2.back(), 100.0);  // it did spread
      }
      // The check can fail: drawn from the left wall, the two lengths put different beads
      // around the kick, and m̃2 parts.
      TransportCase plain_a = a, plain_b = b;
      plain_a.chain.draw().centred = plain_b.chain.draw().centred = false;
      EXPECT_GT(std::fabs(run(plain_a, 0).m2.back() / run(plain_b, 0).m2.back() - 1), 1e-6) << f0 << to_string(d);
    }
}

}  // namespace
}  // namespace granular

namespace granular {
namespace {

TEST(ChainLengthRule, SizingForLongTimesKicksTheCentreOfACentredChain) {
  TransportCase c = long_case(Disorder::anderson, 10, Kick::displacement, 2e-3);
  c.chain.N = 7;
  c.site = 2;
  const ChainLength expected = automatic_chain_length(c);
  const ChainLength got = size_for_long_times(c);
  EXPECT_EQ(got.n, expected.n);
  EXPECT_EQ(c.chain.N, expected.n);
  EXPECT_EQ(c.chain.N % 2, 1u);
  EXPECT_EQ(kicked_bead(c), (c.chain.N - 1) / 2);
  EXPECT_TRUE(c.chain.draw().centred);
  EXPECT_NO_THROW(validate(c));
}

}  // namespace
}  // namespace granular
