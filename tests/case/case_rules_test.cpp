// The run rules of a kicked-chain case decide on the case's real chains (issue "one case, one
// description"): `integrator auto` and the time step see k bead types, a radii file's chain and
// the real mode of a mode kick, and keep SABA2C when anything is damped. Each expectation is
// worked out here by hand, on the chains the rule must try, and the cases are chosen so that the
// old rule (the paper's two radii {R1, ξR1}, a mode built on three beads, damping ignored) would
// decide otherwise.
#include <algorithm>
#include <limits>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "granular/case/mode_kick.hpp"
#include "granular/case/scheme_choice.hpp"
#include "granular/case/time_step_rule.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/error.hpp"
#include "granular/model/chain.hpp"

namespace granular {
namespace {

/// Opening energy of the softest bond, and the largest displacement-kick energy, over every
/// arrangement of `radii` on three beads between walls (every neighbourhood of a bead or bond).
struct Energies {
  double kick = 0, opening = std::numeric_limits<double>::infinity();
};
Energies by_hand(const std::vector<double>& radii, double f0, double alpha) {
  Energies e;
  for (double a : radii)
    for (double b : radii)
      for (double d : radii) {
        const Chain chain = make_chain(std::vector<double>{a, b, d}, f0);
        const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
        for (std::size_t site = 0; site < 3; ++site)
          e.kick = std::max(e.kick, total_energy(law, chain, displacement_kick(chain, site, alpha)));
        const auto& hertz = std::get<HertzLaw>(law);
        for (std::size_t k = 0; k < chain.bonds(); ++k)
          e.opening = std::min(e.opening, hertz.potential(k, -chain.overlap[k]));
      }
  return e;
}

TransportCase paper_case(double alpha) {
  TransportCase c;  // A, q = ξ = 0.5, F0 = 10 N, a displacement kick
  c.alpha = alpha;
  c.dynamics.integration.duration = 1e-3;
  c.fit = false;
  return c;
}

/// An α at which the paper's two radii keep every contact closed but a chain with beads 3 R1
/// large can open one (by the energies): the case where a rule on the wrong radii errs.
double alpha_between(const std::vector<double>& big) {
  for (double alpha = 1e-8; alpha < 1e-5; alpha *= 1.1) {
    const Energies paper = by_hand({4.76e-3, 2.38e-3}, 10, alpha), types = by_hand(big, 10, alpha);
    if (paper.kick < paper.opening && !(types.kick < types.opening)) return alpha;
  }
  return 0;
}

// The case asking for the automatic scheme (the integrator "auto"), settled.
nlohmann::json settle_automatically(TransportCase& c) {
  c.automatic_integrator = true;
  return settle_scheme_and_step(c);
}

TEST(CaseRules, AutoDecidesOnTheKTypesDrawn) {
  const std::vector<double> radii{4.76e-3, 3 * 4.76e-3};
  const double alpha = alpha_between(radii);
  ASSERT_GT(alpha, 0) << "no kick separates the two chains";
  TransportCase paper = paper_case(alpha);
  EXPECT_TRUE(bonds_stay_closed(paper));
  TransportCase types = paper_case(alpha);
  types.chain.source = BeadDistribution{.radii = radii, .probabilities = {0.5, 0.5}};
  EXPECT_FALSE(bonds_stay_closed(types));
  const nlohmann::json rule = settle_automatically(types);
  EXPECT_FALSE(rule["integrator_choice"]["bonds_stay_closed"].get<bool>()) << rule.dump();
  EXPECT_EQ(types.dynamics.integration.integrator.name(), "saba2c");
  EXPECT_TRUE(settle_automatically(paper)["integrator_choice"]["bonds_stay_closed"].get<bool>());
}

TEST(CaseRules, AutoDecidesOnARadiiFilesChain) {
  const std::vector<double> big{4.76e-3, 3 * 4.76e-3};
  const double alpha = alpha_between(big);
  ASSERT_GT(alpha, 0);
  TransportCase file = paper_case(alpha);  // a given chain: big beads at the wall, kicked there
  GivenRadii radii{.radii = std::vector<double>(101, 4.76e-3)};
  for (std::size_t i = 0; i < 11; ++i) radii.radii[i] = 3 * 4.76e-3;
  file.chain.source = radii;
  file.site = 1;
  const Chain chain = file.chain.chain(0);
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  const double energy = total_energy(law, chain, displacement_kick(chain, 0, alpha));
  double opening = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < chain.bonds(); ++k)
    opening = std::min(opening, std::get<HertzLaw>(law).potential(k, -chain.overlap[k]));
  ASSERT_GE(energy, opening) << "the kick on the big beads can open a contact";
  EXPECT_FALSE(bonds_stay_closed(file));
  settle_automatically(file);
  EXPECT_EQ(file.dynamics.integration.integrator.name(), "saba2c");
}

// A mode kick decides on the real mode: mode 2221 of a 2501-bead chain exists (the old rule built
// the mode on three beads and refused K > 3), and its energy is what the rule compares.
TEST(CaseRules, AutoTakesTheRealModeOfAModeKick) {
  TransportCase c = paper_case(1e-7);
  c.kick = Kick::mode;
  c.mode = {.mode = 2221, .energy = 1e-9};
  c.site = 1251;
  const Energies e = by_hand({4.76e-3, 2.38e-3}, 10, 1e-7);
  EXPECT_EQ(bonds_stay_closed(c), 1e-9 < e.opening);
  TransportCase given = c;  // before settling, which fixes c's step
  EXPECT_NO_THROW(settle_automatically(c));
  // On a given chain, with the amplitude α: the mode's own energy.
  given.chain.source = GivenRadii{.radii = paper_case(1e-7).chain.radii(0)};
  given.mode = {.mode = 2221};
  given.alpha = 1e-8;
  const Chain chain = given.chain.chain(0);
  const double energy = mode_kick(chain, ForceLawKind::hertz, {.mode = 2221, .amplitude = 1e-8}).energy;
  const std::vector<Chain> chains = rule_chains(given);
  ASSERT_EQ(chains.size(), 1u);
  EXPECT_DOUBLE_EQ(kick_energy_bound(given, chains, true), energy);
  EXPECT_NO_THROW(settle_automatically(given));
}

// Damping is composed with any scheme by a 2nd-order splitting: auto keeps SABA2C at its rule
// step, and says so.
TEST(CaseRules, AutoKeepsSaba2cWhenDamped) {
  TransportCase plain = paper_case(1e-7);
  settle_automatically(plain);
  ASSERT_EQ(plain.dynamics.integration.integrator.name(), "srkn14a");
  for (const Damping damping : {Damping{.time = 1e-3}, Damping{.kk_gamma = 1e-6}}) {
    TransportCase damped = paper_case(1e-7);
    damped.dynamics.integration.damping = damping;
    const nlohmann::json rule = settle_automatically(damped);
    EXPECT_EQ(damped.dynamics.integration.integrator.name(), "saba2c");
    EXPECT_EQ(damped.dynamics.integration.time_step, 1e-6);
    EXPECT_TRUE(rule["integrator_choice"]["damped"].get<bool>());
    EXPECT_TRUE(rule["integrator_choice"]["bonds_stay_closed"].get<bool>());
  }
}

}  // namespace
}  // namespace granular
