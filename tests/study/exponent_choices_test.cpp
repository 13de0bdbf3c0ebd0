// The exponent table's chains and kicks in words, chosen once for the tool and Python: the kinds
// and kicks parsed ("none" alone: no kind), one chain beyond the kinds under its name (by default
// types, polydisperse or quasi-KIND), its drawing rule only with k types; each refusal names the
// choice, and good words fill the table as before.
#include "granular/study/exponent_choices.hpp"

#include <gtest/gtest.h>

#include <string>

#include "granular/error.hpp"

namespace granular {
namespace {

/// The parameter `o` is refused for, or "" when it is taken.
std::string exponent_words_refused(const ExponentChoices& o) {
  ExponentTableConfig config;
  try {
    apply(o, config);
  } catch (const InvalidInput& e) {
    return e.parameter();
  }
  return "";
}

TEST(ExponentChoices, TheDefaultsAreThePapersKindsAndKicks) {
  ExponentTableConfig config;
  config.chains.clear();
  config.kicks.clear();
  const ExponentChoices words;
  apply(words, config);
  EXPECT_EQ(config.chains,
            (std::vector<Disorder>{Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2}));
  EXPECT_EQ(config.kicks, (std::vector<Kick>{Kick::displacement, Kick::velocity}));
  EXPECT_TRUE(config.bead_chains.empty());
  EXPECT_EQ(chain_list(words), "h,A,RDM1,RDM2");
  EXPECT_EQ(kick_list(words), "displacement,velocity");
}

TEST(ExponentChoices, OneChainBeyondTheKindsJoinsByName) {
  ExponentTableConfig config;
  ExponentChoices words{.chains = {"none"}, .ic = {"velocity", "mode"}};
  words.beads.types = "4.76e-3:0.3,2.38e-3:0.7";
  words.types_rule = "RDM1";
  apply(words, config);
  EXPECT_TRUE(config.chains.empty());
  EXPECT_EQ(chain_list(words), "none");
  EXPECT_EQ(config.kicks, (std::vector<Kick>{Kick::velocity, Kick::mode}));
  ASSERT_EQ(config.bead_chains.size(), 1u);
  EXPECT_EQ(config.bead_chains[0].name, "types");
  EXPECT_EQ(config.bead_chains[0].beads.rule, Disorder::rdm1);
  EXPECT_EQ(config.bead_chains[0].beads.radii, (std::vector<double>{4.76e-3, 2.38e-3}));

  words = ExponentChoices{.chains = {"A"}, .chain_name = "mine"};
  words.beads.polydisperse = "uniform:2e-3:3e-3";
  apply(words, config);
  ASSERT_EQ(config.bead_chains.size(), 1u);  // replaced, not added to
  EXPECT_EQ(config.bead_chains[0].name, "mine");
  EXPECT_EQ(config.bead_chains[0].beads.kind, BeadDistribution::Kind::uniform);

  words = ExponentChoices{.chains = {}};
  words.beads.quasi = "s1";
  words.beads.modulation = 0.5;
  apply(words, config);
  ASSERT_EQ(config.bead_chains.size(), 1u);
  EXPECT_EQ(config.bead_chains[0].name, "quasi-s1");
  ASSERT_TRUE(config.bead_chains[0].quasi);
  EXPECT_EQ(config.bead_chains[0].quasi->modulation, 0.5);
}

TEST(ExponentChoices, ABadWordIsRefusedByName) {
  EXPECT_EQ(exponent_words_refused({.chains = {"A", "X"}}), "chains");
  EXPECT_EQ(exponent_words_refused({.chains = {"none"}}), "chains");  // no chain at all
  EXPECT_EQ(exponent_words_refused({.chains = {}}), "chains");
  EXPECT_EQ(exponent_words_refused({.ic = {"push"}}), "ic");
  EXPECT_EQ(exponent_words_refused({.ic = {}}), "ic");
  EXPECT_EQ(exponent_words_refused({.types_rule = "RDM1"}), "types_rule");  // without types
  EXPECT_EQ(exponent_words_refused({.chain_name = "mine"}), "chain_name");  // without a chain of one's own
  ExponentChoices typed;
  typed.beads.types = "4.76e-3:0.5,2e-3:0.5";
  typed.types_rule = "X";
  EXPECT_EQ(exponent_words_refused(typed), "types_rule");
  typed.types_rule = "";
  typed.chain_name = "RDM1";  // a kind's name
  EXPECT_EQ(exponent_words_refused(typed), "chain_name");
  typed.chain_name = "a,b";
  EXPECT_EQ(exponent_words_refused(typed), "chain_name");
  typed.chain_name = "";
  typed.beads.quasi = "s1";
  EXPECT_EQ(exponent_words_refused(typed), "quasi");
  ExponentChoices quasi;
  quasi.beads.quasi = "s4";
  EXPECT_EQ(exponent_words_refused(quasi), "quasi");
}

TEST(ExponentChoices, AChainKindIsToldAsTheChainsChoice) {
  ExponentTableConfig config;
  try {
    apply(ExponentChoices{.chains = {"A", "X"}}, config);
    FAIL() << "X taken";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "chains 'X': expected one of h, A, RDM1, RDM2");
  }
}

TEST(ExponentChoices, TheModeOfAModeKickReachesEveryCaseOnlyWithThatKick) {
  ExponentTableConfig config;
  apply(ExponentChoices{.chains = {"A"}, .ic = {"mode"}, .mode = {.mode = 7, .energy = 1e-9}}, config);
  EXPECT_EQ(config.kicks, std::vector<Kick>{Kick::mode});
  EXPECT_EQ(config.base.mode.mode, 7);
  EXPECT_EQ(config.base.mode.energy, 1e-9);
  for (const TransportCase& c : exponent_cases(config)) EXPECT_EQ(c.mode.mode, 7) << "every case kicks mode 7";
  EXPECT_THROW(apply(ExponentChoices{.ic = {"displacement"}, .mode = {.mode = 7}}, config), InvalidInput)
      << "a mode without ic mode";
}

}  // namespace
}  // namespace granular
