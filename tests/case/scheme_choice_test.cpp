// --integrator auto: SRKN14a only where no contact can open, and only when cheaper; the opening
// test agrees with the energies it compares (a kick just below and just above the opening energy).
#include "granular/case/scheme_choice.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "granular/case/time_step_rule.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/error.hpp"
#include "granular/model/chain.hpp"

namespace granular {
namespace {

TransportCase homogeneous(double f0, double alpha) {
  TransportCase c;
  c.chain.draw().disorder = Disorder::homogeneous;
  c.chain.F0 = f0;
  c.alpha = alpha;
  c.chain.N = 3;
  c.site = 2;
  return c;
}

TEST(SchemeChoice, SonicVacuumAndStrongKicksOpenContacts) {
  EXPECT_TRUE(bonds_stay_closed(homogeneous(10, 1e-7)));
  EXPECT_FALSE(bonds_stay_closed(homogeneous(0, 1e-7)));
  EXPECT_FALSE(bonds_stay_closed(homogeneous(10, 1e-5)));  // stretches a bond past its overlap
  TransportCase linear = homogeneous(0, 1e-5);
  linear.dynamics.integration.force_law = ForceLawKind::linear;
  EXPECT_TRUE(bonds_stay_closed(linear));
}

// A displacement α of the centre bead of a homogeneous chain stretches one bond by α: it can open
// exactly when α passes the static overlap, whatever the energy bookkeeping says elsewhere; the
// energy test is sufficient, so it must say "closed" below a fraction of the overlap and "open"
// past it.
TEST(SchemeChoice, TheOpeningTestBracketsTheStaticOverlap) {
  const Chain chain = make_chain(std::vector<double>(3, 4.76e-3), 10);
  const double overlap = chain.overlap[1];
  EXPECT_TRUE(bonds_stay_closed(homogeneous(10, 0.3 * overlap)));
  EXPECT_FALSE(bonds_stay_closed(homogeneous(10, 1.01 * overlap)));
}

TEST(SchemeChoice, TheCheaperWins) {
  EXPECT_EQ(choose_scheme(1e-6, 5e-6, true).integrator, "srkn14a");
  EXPECT_NEAR(choose_scheme(1e-6, 5e-6, true).relative_cost, 0.8, 1e-12);
  EXPECT_EQ(choose_scheme(1e-6, 2.5e-6, true).integrator, "saba2c");  // 1.6x dearer
  EXPECT_EQ(choose_scheme(1e-6, 5e-6, false).integrator, "saba2c");
  EXPECT_EQ(choose_scheme(0.5e-6, 2.5e-6, true).integrator, "srkn14a");
}

// The benchmark chain's ω_max (time_step_rule.hpp) is the one the constant was taken from: it
// keeps 5 µs there; a stiffer chain gets 5 µs/k.
TEST(SchemeChoice, TheBenchmarkChainKeepsFiveMicroseconds) {
  TransportCase c;  // A, ξ = q = 0.5, F0 = 10 N, α = 1e-7 m: the cost-accuracy benchmark
  const double omega = time_step_limit(c).omega_max;
  EXPECT_NEAR(omega, 2.9355e5, 0.0001e5);
  EXPECT_EQ(srkn14a_default_step(omega), 5e-6);
  EXPECT_EQ(srkn14a_default_step(2.5 * omega), 5e-6 / 3);
}

// The study-level choice (what `--integrator auto` and Python's integrator='auto' call): SRKN14a at
// 5 µs on the precompressed benchmark chain, SABA2C at its stability-rule step in the sonic
// vacuum, one scheme for every case of a study (the dearest case decides), a given τ refused.
TEST(SchemeChoice, SettlesOneSchemeAndStepForAStudy) {
  TransportCase closed;  // A, F0 = 10 N, displacement kick of 0.1 µm, integrator auto
  closed.automatic_integrator = true;
  TransportCase open = closed;
  open.chain.F0 = 0;
  std::vector<TransportCase> one{closed};
  const nlohmann::json rule = settle_scheme_and_step(one);
  EXPECT_EQ(one.front().dynamics.integration.integrator.name(), "srkn14a");
  EXPECT_EQ(one.front().dynamics.integration.time_step, 5e-6);
  EXPECT_EQ(rule["integrator_choice"]["integrator"], "srkn14a");
  EXPECT_EQ(rule["time_step_given"], false);
  std::vector<TransportCase> both{closed, open};
  settle_scheme_and_step(both);
  for (const TransportCase& c : both) {
    EXPECT_EQ(c.dynamics.integration.integrator.name(), "saba2c");
    EXPECT_EQ(c.dynamics.integration.time_step, 1e-6);
  }
  std::vector<TransportCase> given{closed};
  given.front().time_step = 1e-6;
  try {
    settle_scheme_and_step(given);
    ADD_FAILURE() << "a given time step with the automatic choice must be refused";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "dt");
  }
  // Not automatic: the time-step rule alone, the scheme untouched.
  std::vector<TransportCase> plain{closed};
  plain.front().automatic_integrator = false;
  const nlohmann::json same = settle_scheme_and_step(plain);
  EXPECT_EQ(plain.front().dynamics.integration.integrator.name(), "saba2c");
  EXPECT_FALSE(same.contains("integrator_choice"));
}

}  // namespace
}  // namespace granular
