// The exponent table as front ends choose it, once for the tool and Python: its kinds, kicks,
// precompressions and profiles as rows over the config itself (text forms read what they write;
// "none" alone: no kind), one chain beyond the kinds in words under its name (by default types,
// polydisperse or quasi-KIND), its drawing rule only with k types; each refusal names the choice,
// and good words fill the table as before.
#include "granular/study/exponent_choices.hpp"

#include <gtest/gtest.h>

#include <string>

#include "granular/error.hpp"

namespace granular {
namespace {

/// Reads `text` into `config` by the table row `name`.
void read_row(ExponentTableConfig& config, const std::string& name, const std::string& text) {
  parameter(exponent_table_parameters(), name).text->read(config, text);
}

/// The parameter refused, or "" when taken: the rows' texts read into a default config, then `o`.
std::string exponent_words_refused(const ExponentChoices& o,
                                   const std::vector<std::pair<std::string, std::string>>& rows = {}) {
  ExponentTableConfig config;
  try {
    for (const auto& [name, text] : rows) read_row(config, name, text);
    set_chains(o, config);
  } catch (const InvalidInput& e) {
    return e.parameter();
  }
  return "";
}

TEST(ExponentChoices, TheDefaultsAreThePapersKindsAndKicks) {
  ExponentTableConfig config;
  set_chains(ExponentChoices{}, config);
  EXPECT_EQ(config.chains,
            (std::vector<Disorder>{Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2}));
  EXPECT_EQ(config.kicks, (std::vector<Kick>{Kick::displacement, Kick::velocity}));
  EXPECT_TRUE(config.bead_chains.empty());
  EXPECT_EQ(chain_list(config), "h,A,RDM1,RDM2");
  EXPECT_EQ(kick_list(config), "displacement,velocity");
  const auto& rows = exponent_table_parameters();
  EXPECT_EQ(parameter(rows, "F0").text->write(config), "10,0.5,0.1,0.01,0");
  EXPECT_EQ(parameter(rows, "profile_F0").text->write(config), "10,0.1,0");
  EXPECT_EQ(config.base.realizations, 500u);
  EXPECT_EQ(config.profile_realizations, 100u);
}

TEST(ExponentChoices, TheTablesRowsReachTheConfig) {
  ExponentTableConfig config;
  read_row(config, "chains", "a,rdm2");
  read_row(config, "ic", "velocity,mode");
  read_row(config, "F0", "1,0.5");
  read_row(config, "profile_F0", "none");
  EXPECT_EQ(config.chains, (std::vector<Disorder>{Disorder::anderson, Disorder::rdm2}));
  EXPECT_EQ(chain_list(config), "A,RDM2") << "the kinds as the library names them";
  EXPECT_EQ(config.kicks, (std::vector<Kick>{Kick::velocity, Kick::mode}));
  EXPECT_EQ(config.precompressions, (std::vector<double>{1, 0.5}));
  EXPECT_TRUE(config.profile_precompressions.empty());
  EXPECT_EQ(parameter(exponent_table_parameters(), "profile_F0").text->write(config), "none");
  read_row(config, "chains", "none");
  EXPECT_TRUE(config.chains.empty());
  EXPECT_EQ(chain_list(config), "none");
}

TEST(ExponentChoices, OneChainBeyondTheKindsJoinsByName) {
  ExponentTableConfig config;
  config.chains.clear();
  config.kicks = {Kick::velocity, Kick::mode};
  ExponentChoices words;
  words.beads.types = "4.76e-3:0.3,2.38e-3:0.7";
  words.types_rule = "RDM1";
  set_chains(words, config);
  ASSERT_EQ(config.bead_chains.size(), 1u);
  EXPECT_EQ(config.bead_chains[0].name, "types");
  EXPECT_EQ(config.bead_chains[0].beads.rule, Disorder::rdm1);
  EXPECT_EQ(config.bead_chains[0].beads.radii, (std::vector<double>{4.76e-3, 2.38e-3}));

  words = ExponentChoices{.chain_name = "mine"};
  words.beads.polydisperse = "uniform:2e-3:3e-3";
  set_chains(words, config);
  ASSERT_EQ(config.bead_chains.size(), 1u);  // replaced, not added to
  EXPECT_EQ(config.bead_chains[0].name, "mine");
  EXPECT_EQ(config.bead_chains[0].beads.kind, BeadDistribution::Kind::uniform);

  words = ExponentChoices{};
  words.beads.quasi = "s1";
  words.beads.modulation = 0.5;
  set_chains(words, config);
  ASSERT_EQ(config.bead_chains.size(), 1u);
  EXPECT_EQ(config.bead_chains[0].name, "quasi-s1");
  ASSERT_TRUE(config.bead_chains[0].quasi);
  EXPECT_EQ(config.bead_chains[0].quasi->modulation, 0.5);
}

TEST(ExponentChoices, ABadWordIsRefusedByName) {
  EXPECT_EQ(exponent_words_refused({}, {{"chains", "A,X"}}), "chains");
  EXPECT_EQ(exponent_words_refused({}, {{"chains", "none"}}), "chains");  // no chain at all
  EXPECT_EQ(exponent_words_refused({}, {{"ic", "push"}}), "ic");
  EXPECT_EQ(exponent_words_refused({}, {{"F0", "ten"}}), "F0");
  EXPECT_EQ(exponent_words_refused({.types_rule = "RDM1"}), "types_rule");  // without types
  EXPECT_EQ(exponent_words_refused({.chain_name = "mine"}), "chain_name");  // without a chain of one's own
  ExponentTableConfig no_kick;
  no_kick.kicks.clear();
  EXPECT_THROW(set_chains({}, no_kick), InvalidInput);
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
  try {
    parse_chain_kinds({"A", "X"});
    FAIL() << "X taken";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "chains 'X': expected one of h, A, RDM1, RDM2");
  }
}

TEST(ExponentChoices, TheModeOfAModeKickReachesEveryCaseOnlyWithThatKick) {
  ExponentTableConfig config;
  config.chains = {Disorder::anderson};
  config.kicks = {Kick::mode};
  config.base.mode = {.mode = 7, .energy = 1e-9};
  set_chains({}, config);
  for (const TransportCase& c : exponent_cases(config)) EXPECT_EQ(c.mode.mode, 7) << "every case kicks mode 7";
  config.kicks = {Kick::displacement};
  EXPECT_THROW(set_chains({}, config), InvalidInput) << "a mode without ic mode";
}

}  // namespace
}  // namespace granular
