// The front ends' rules on a kicked-chain case, spelled once: "auto" stands for SABA2C until the
// step is settled, a fit window past T means no exponents (not an error), and a mode kick's own
// fields are told apart from their defaults.
#include "granular/study/transport_choices.hpp"

#include <gtest/gtest.h>

namespace granular {
namespace {

TEST(TransportChoices, AutoStandsForSaba2cUntilSettled) {
  TransportChoices choices;
  TransportCase c;
  apply(choices, c);
  EXPECT_FALSE(c.automatic_integrator);
  EXPECT_EQ(c.dynamics.integration.integrator.name(), "saba2c");
  choices.integrator = "srkn14a";
  apply(choices, c);
  EXPECT_FALSE(c.automatic_integrator);
  EXPECT_EQ(c.dynamics.integration.integrator.name(), "srkn14a");
  choices.integrator = "auto";
  apply(choices, c);
  EXPECT_TRUE(c.automatic_integrator);  // settled with the step (scheme_choice.hpp)
  EXPECT_EQ(c.dynamics.integration.integrator.name(), "saba2c");
}

// What settling resolves travels in the case, not beside it: a time step given or not.
TEST(TransportChoices, AGivenTimeStepIsTheCasesOwnAndNoneLeavesThePreferredOne) {
  TransportChoices choices;
  TransportCase c;
  const double preferred = c.dynamics.integration.time_step;
  apply(choices, c);
  EXPECT_FALSE(c.time_step.has_value());
  EXPECT_EQ(c.dynamics.integration.time_step, preferred);
  choices.time_step = 2.5e-7;
  apply(choices, c);
  ASSERT_TRUE(c.time_step.has_value());
  EXPECT_EQ(*c.time_step, 2.5e-7);
  EXPECT_EQ(c.dynamics.integration.time_step, 2.5e-7);
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
