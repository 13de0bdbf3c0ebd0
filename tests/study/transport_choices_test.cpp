// The front ends' rules on a kicked-chain case, spelled once: "auto" stands for SABA2C until the
// step is settled, a fit window past T means no exponents (not an error), and a mode kick's own
// fields are told apart from their defaults.
#include "granular/study/transport_choices.hpp"

#include <gtest/gtest.h>

namespace granular {
namespace {

TEST(TransportChoices, AutoStandsForSaba2cUntilSettled) {
  TransportChoices choices;
  EXPECT_FALSE(take_automatic_integrator(choices));
  EXPECT_EQ(choices.integrator, "saba2c");
  choices.integrator = "srkn14a";
  EXPECT_FALSE(take_automatic_integrator(choices));
  EXPECT_EQ(choices.integrator, "srkn14a");
  choices.integrator = "auto";
  EXPECT_TRUE(take_automatic_integrator(choices));
  EXPECT_EQ(choices.integrator, "saba2c");
  TransportCase c;
  apply(choices, c);  // what the case stands for is a scheme apply() knows
  EXPECT_EQ(c.dynamics.integration.integrator.name(), "saba2c");
}

TEST(TransportChoices, AFitWindowPastTheDurationFitsNothing) {
  TransportCase c;
  c.dynamics.integration.duration = 1e-2;
  c.fit_end = 1e-2;
  fit_within_duration(c);
  EXPECT_TRUE(c.fit);
  c.fit_end = 1e-2 * (1 + 1e-13);  // rounding of a typed T
  fit_within_duration(c);
  EXPECT_TRUE(c.fit);
  c.fit_end = 1.1e-2;
  fit_within_duration(c);
  EXPECT_FALSE(c.fit);
  c.dynamics.integration.duration = 2e-2;
  fit_within_duration(c);
  EXPECT_TRUE(c.fit);
}

TEST(TransportChoices, AModeKicksOwnFieldsAreToldFromTheirDefaults) {
  EXPECT_FALSE(chosen(ModeKick{}));
  EXPECT_FALSE(chosen(ModeKick{.amplitude = 1e-7}));  // the amplitude is any kick's α
  EXPECT_TRUE(chosen(ModeKick{.mode = 3}));
  EXPECT_TRUE(chosen(ModeKick{.near_khz = 0}));
  EXPECT_TRUE(chosen(ModeKick{.energy = 1e-9}));
}

}  // namespace
}  // namespace granular
