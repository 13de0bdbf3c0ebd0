// The kicked case a front end chooses (case/kicked_case.hpp): the case is the one the parts'
// own rules give (chain_recipe, the typed case as set), --N auto sizes the chain around a centre kick and says
// by which rule, an ensemble refuses a chain that is not random, and a case file gives back the
// case that was written, with the realizations asked for.
#include "granular/case/kicked_case.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "granular/case/case_file.hpp"
#include "granular/case/chain_length_rule.hpp"
#include "granular/error.hpp"
#include "scratch.hpp"

namespace granular {
namespace {

const RadiusNames names{"R1", "beads", "radii"};

/// The chain in words and the typed case, as a front end fills them.
struct KickedChoices {
  ChainChoices chain = kicked_chain_defaults();
  TransportCase run = [] {
    TransportCase c;
    c.realizations = 1;
    return c;
  }();
};

KickedCase kicked_case_of(const KickedChoices& o, bool ensemble) {
  return kicked_case(o.chain, o.run, ensemble, names);
}

std::string refused_parameter(const KickedChoices& o, bool ensemble) {
  try {
    kicked_case_of(o, ensemble);
  } catch (const InvalidInput& e) {
    return e.parameter().empty() ? e.what() : e.parameter();
  }
  return "(accepted)";
}

TEST(KickedCase, IsTheCaseThePartsRulesGive) {
  KickedChoices o;
  o.chain.disorder = "RDM1", o.chain.n = 201, o.chain.seed = 4, o.chain.realization = 2;
  o.run.kick = Kick::velocity, o.run.dynamics.integration.duration = 2e-3, o.run.fit_begin = 1e-3, o.run.fit_end = 3e-3,
  o.run.realizations = 7;
  o.run.dynamics.integration.damping.time = 1e-2;
  const KickedCase k = kicked_case_of(o, true);

  TransportCase expected = o.run;
  std::vector<std::string> warnings;
  expected.chain = chain_recipe(o.chain, warnings);
  expected.kick = Kick::velocity;
  fit_within_duration(expected);
  expected.realizations = 7;
  expected.profile_realizations = 0;
  EXPECT_EQ(describe(k.c), describe(expected));
  EXPECT_FALSE(k.c.fit) << "the fit window ends past T: no exponents";
  EXPECT_EQ(k.selected.realization, 2u);
  EXPECT_EQ(k.selected.chain.size(), 201u);
  EXPECT_EQ(k.selected.description, describe(expected.chain, 2));
  EXPECT_TRUE(k.warnings.empty());
}

TEST(KickedCase, AutomaticLengthSizesTheChainAroundACentreKick) {
  KickedChoices o;
  o.chain.auto_n = true, o.chain.n = 3, o.run.dynamics.integration.duration = 1e-3, o.run.fit_begin = 4e-4,
  o.run.fit_end = 1e-3;
  const KickedCase k = kicked_case_of(o, false);
  const std::size_t n = automatic_chain_length(k.c).n;
  EXPECT_GT(n, 3u);
  EXPECT_EQ(k.c.chain.N, n);
  EXPECT_EQ(k.selected.chain.size(), n);
  EXPECT_EQ(kicked_bead(k.c), (n - 1) / 2);
  EXPECT_EQ(k.selected.description["N_rule"]["N"], n);
  o.run.site = 2;
  EXPECT_EQ(refused_parameter(o, false), "site") << "auto N kicks the centre bead";
}

TEST(KickedCase, AnEnsembleDrawsRandomChains) {
  const std::string radii = testing::scratch_path("kicked-case", "radii.txt");
  std::ofstream(radii) << "4.76e-3\n3e-3\n4.76e-3\n3e-3\n4.76e-3\n";
  KickedChoices o;
  o.chain.radii = radii, o.run.dynamics.integration.duration = 1e-4, o.run.fit_begin = 5e-5, o.run.fit_end = 1e-4;
  EXPECT_EQ(refused_parameter(o, false), "(accepted)");
  const std::string refusal = refused_parameter(o, true);
  EXPECT_NE(refusal.find("`realizations`"), std::string::npos) << refusal;
  o.chain.radii.clear(), o.run.realizations = 0;
  EXPECT_EQ(refused_parameter(o, false), "realizations");
}

TEST(KickedCase, AModeIsChosenOnlyForAModeKick) {
  KickedChoices o;
  o.chain.n = 51, o.run.dynamics.integration.duration = 1e-4, o.run.fit_begin = 5e-5, o.run.fit_end = 1e-4;
  o.run.mode.mode = 3;
  const std::string refusal = refused_parameter(o, false);
  EXPECT_NE(refusal.find("only with `ic` mode"), std::string::npos) << refusal;
  o.run.kick = Kick::mode;
  EXPECT_EQ(refused_parameter(o, false), "(accepted)");
}

TEST(KickedCase, ItsRowsReachTheCaseFields) {
  TransportCase c;
  const ParameterTable<TransportCase>& rows = kicked_case_parameters();
  ASSERT_EQ(rows.size(), 2u);
  parameter(rows, "ic").text->read(c, "mode");
  std::get<Ref<TransportCase, unsigned long>>(parameter(rows, "realizations").field)(c) = 12;
  EXPECT_EQ(c.kick, Kick::mode);
  EXPECT_EQ(c.realizations, 12u);
  EXPECT_EQ(parameter(rows, "ic").text->write(c), "mode");
  EXPECT_THROW(parameter(rows, "ic").text->read(c, "kick"), InvalidInput) << "not a kick";
}

TEST(KickedCase, ACaseFileGivesBackTheCaseWritten) {
  KickedChoices o;
  o.chain.disorder = "A", o.chain.n = 51, o.chain.seed = 3, o.run.kick = Kick::displacement,
  o.run.dynamics.integration.duration = 5e-4;
  o.run.fit_begin = 2e-4, o.run.fit_end = 5e-4, o.run.dynamics.integration.lyapunov.enabled = true,
  o.run.realizations = 5;
  const KickedCase written = kicked_case_of(o, true);
  const std::string path = write_replay_case(written.c, 3, testing::scratch_path("kicked-case", "run"));
  const KickedCase read = kicked_case(path, 3, 5, 20, true);
  TransportCase expected = written.c;
  expected.dynamics.deviation_samples = 20;
  EXPECT_EQ(describe(read.c), describe(expected));
  EXPECT_EQ(read.selected.realization, 3u);
  EXPECT_EQ(read.selected.chain.size(), 51u);
  EXPECT_THROW(kicked_case(path, -1, 1, 0, false), InvalidInput);
}

}  // namespace
}  // namespace granular
