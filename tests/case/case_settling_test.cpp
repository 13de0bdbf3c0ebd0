// The order of a study case's errors (case_settling.hpp): a τ past the stability limit is named
// as such before a --fit-step or a T judged on its grid, which validate() alone would name first;
// a τ that is stable still has its grid checked; and the duration warning uses the ω_max the step
// rule found, the same as the rule computed anew.
#include "granular/case/case_settling.hpp"

#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "granular/case/chain_length_rule.hpp"
#include "granular/case/time_step_rule.hpp"
#include "granular/dynamics/integrator.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

// The parameter a throwing call names ("" when it does not throw).
template <class F>
std::string case_settling_named(F&& call) {
  try {
    call();
  } catch (const InvalidInput& e) {
    return e.parameter();
  }
  return "";
}

TEST(CaseSettling, ATimeStepPastStabilityIsNamedBeforeTheFitStepOnItsGrid) {
  TransportCase c;  // the paper's A chain, 2,501 beads, fits sampled every 10 µs
  c.time_step = c.dynamics.integration.time_step =
      1e-4;  // given, 10× the fit step, and ~10× the stability limit (~9.8 µs)
  ASSERT_GT(c.dynamics.integration.time_step, time_step_limit(c).max_time_step);
  EXPECT_EQ(case_settling_named([&] { validate(c); }), "fit_step");  // the order this replaces
  EXPECT_EQ(case_settling_named([&] { validate_before_time_step(c); }), "");
  std::string warning;
  EXPECT_EQ(case_settling_named([&] { validate_and_settle(c, "--T", warning); }), "time_step");
}

TEST(CaseSettling, AStableTimeStepStillHasItsGridChecked) {
  TransportCase c;
  c.time_step = 2e-6;  // given, stable; T = 5000 steps, but the fit step 5 µs is 2.5 steps
  c.fit_step = 5e-6;
  std::string warning;
  EXPECT_EQ(case_settling_named([&] { validate_and_settle(c, "--T", warning); }), "fit_step");
  c.fit_step = 1e-5;  // 5 steps
  std::vector<TransportCase> cases{c};
  EXPECT_NO_THROW(validate_and_settle(cases, "--T", warning));
  EXPECT_EQ(warning, "");  // 10 ms on 2,501 beads: waves reach no wall
}

TEST(CaseSettling, TheDurationWarningUsesTheRulesOmegaMax) {
  TransportCase c;
  c.chain.N = 101;
  c.site = 51;
  c.fit = false;
  c.dynamics.integration.duration = 1;  // 1 s typed for 1 ms: waves cross 101 beads thousands of times
  std::string warning;
  const nlohmann::json rule = validate_and_settle(c, "--T", warning);
  const double omega_max = time_step_limit(c).omega_max;  // anew, as the warning once did
  EXPECT_DOUBLE_EQ(rule.at("omega_max_rad_s").get<double>(), omega_max);
  EXPECT_EQ(warning, duration_warning(c, omega_max, "--T"));
  EXPECT_EQ(warning.rfind("--T 1:", 0), 0u) << warning;
  // At the threshold: v T = 10 × the 51 beads to the nearer wall, v = ω_max/2; just below it, none.
  c.dynamics.integration.duration = 0.99 * 10 * 51 / (omega_max / 2);
  EXPECT_EQ(duration_warning(c, omega_max, "--T"), "");
  c.dynamics.integration.duration = 1.01 * 10 * 51 / (omega_max / 2);
  EXPECT_NE(duration_warning(c, omega_max, "--T"), "");
}

TEST(CaseSettling, TheReferenceIntegratorStillBoundsTheWaves) {
  TransportCase c;
  c.dynamics.integration.integrator = parse_integrator("reference");
  const TimeStepLimit limit = time_step_limit(c);
  TransportCase split = c;
  split.dynamics.integration.integrator = saba2c();
  EXPECT_EQ(limit.omega_max, time_step_limit(split).omega_max);  // the chain's bound, not the scheme's
  EXPECT_EQ(limit.max_time_step, std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace granular
