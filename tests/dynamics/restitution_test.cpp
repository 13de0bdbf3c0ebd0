// The coefficient of restitution of a two-bead Kuwabara–Kono collision (docs/physics.md, "Nonlinear dynamics" "Beyond the
// paper"): elastic without damping, falling with γ_KK and with the impact speed, and
// 1 − e ∝ γ_KK v^{1/5} with Schwager & Pöschel's coefficient at small damping.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "granular/dynamics/restitution.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

TEST(Restitution, ElasticWithoutDamping) {
  for (double v : {1e-3, 0.1, 1.0}) {
    const Collision c = two_bead_collision({.impact_speed = v});
    std::printf("  v = %g m/s: 1 - e = %.2e, contact time %.4g us (Hertz %.4g us)\n", v, 1 - c.restitution,
                c.contact_time * 1e6, c.hertz_time * 1e6);
    EXPECT_NEAR(c.restitution, 1.0, 1e-9);
    EXPECT_EQ(c.dissipated, 0.0);
    // The contact closes within one step of the analytic Hertz contact time.
    EXPECT_NEAR(c.contact_time, c.hertz_time, 1.5 * c.time_step);
  }
}

TEST(Restitution, FallsWithDampingAndWithImpactSpeed) {
  double previous = 1.0;
  for (double gamma : {1e-7, 1e-6, 1e-5}) {
    const double e = two_bead_collision({.impact_speed = 0.1, .kk_gamma = gamma}).restitution;
    EXPECT_LT(e, previous) << "gamma " << gamma;
    previous = e;
  }
  previous = 1.0;
  for (double v : {1e-3, 1e-2, 1e-1, 1.0}) {
    const Collision c = two_bead_collision({.impact_speed = v, .kk_gamma = 1e-6});
    EXPECT_LT(c.restitution, previous) << "v " << v;
    // The kinetic energy lost is what the damping removed.
    const double lost = c.initial_energy * (1 - c.restitution * c.restitution) / 2;  // equal masses, CM frame
    EXPECT_NEAR(c.dissipated / lost, 1.0, 1e-6) << "v " << v;
    previous = c.restitution;
  }
}

TEST(Restitution, DeficitGrowsAsTheFifthRootOfTheImpactSpeed) {
  // Small damping: fit ln(1 − e) against ln v over a decade of v (0.01 … 0.1 m/s).
  const double gamma = 1e-7;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int count = 0;
  for (double v = 0.01; v <= 0.1 * 1.0001; v *= std::pow(10.0, 0.25)) {
    const CollisionConfig config{.impact_speed = v, .kk_gamma = gamma};
    const double deficit = 1 - two_bead_collision(config).restitution;
    const double predicted = restitution_deficit_small_damping(config);
    std::printf("  v = %.4f m/s: 1 - e = %.5e, Schwager-Poeschel %.5e\n", v, deficit, predicted);
    EXPECT_NEAR(deficit / predicted, 1.0, 0.02);  // leading order in the damping
    const double x = std::log(v), y = std::log(deficit);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++count;
  }
  const double slope = (count * sxy - sx * sy) / (count * sxx - sx * sx);
  std::printf("  fitted exponent %.4f (theory 1/5)\n", slope);
  EXPECT_NEAR(slope, 0.2, 0.005);
}

TEST(Restitution, RejectsBadInput) {
  EXPECT_THROW(two_bead_collision({.impact_speed = 0}), InvalidInput);
  EXPECT_THROW(two_bead_collision({.impact_speed = 0.1, .kk_gamma = -1}), InvalidInput);
  EXPECT_THROW(two_bead_collision({.radius = -1}), InvalidInput);
}

}  // namespace
}  // namespace granular
