// A chain in a front end's words: the recipe it gives is the one spelled field by field, the
// bead distributions' and the quasiperiodic chain's texts are read, each error names the choice
// in the library's vocabulary, and a radii file's implausible radii come back as warnings.
#include "granular/case/chain_choices.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "granular/error.hpp"
#include "scratch.hpp"

namespace granular {
namespace {

std::string chain_choices_parameter(const ChainChoices& o) {
  std::vector<std::string> warnings;
  try {
    chain_recipe(o, warnings);
  } catch (const InvalidInput& e) {
    return e.parameter();
  }
  return "(accepted)";
}

TEST(ChainChoices, GiveTheRecipeSpelledFieldByField) {
  ChainChoices o;
  o.disorder = "RDM2", o.q = 0.8, o.xi = 0.6, o.f0 = 0.5, o.r1 = 3e-3, o.n = 301, o.seed = 7, o.walls = "sphere";
  std::vector<std::string> warnings;
  const ChainRecipe r = chain_recipe(o, warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(r.draw().disorder, Disorder::rdm2);
  EXPECT_EQ(r.draw().q, 0.8);
  EXPECT_EQ(r.xi(), 0.6);
  EXPECT_EQ(r.F0, 0.5);
  EXPECT_EQ(r.R1, 3e-3);
  EXPECT_EQ(r.N, 301u);
  EXPECT_EQ(r.seed, 7u);
  EXPECT_EQ(r.walls, WallShape::sphere);
  EXPECT_FALSE(r.draw().centred);
  EXPECT_FALSE(r.as<BeadDistribution>() || r.as<Quasiperiodic>() || r.as<GivenTypes>() || r.as<GivenRadii>());
  ChainRecipe spelled{.source = TwoTypeDraw{.disorder = Disorder::rdm2, .q = 0.8, .xi = 0.6},
                      .R1 = 3e-3,
                      .N = 301,
                      .F0 = 0.5,
                      .seed = 7};
  spelled.walls = WallShape::sphere;
  EXPECT_EQ(r.chain(3).radius, spelled.chain(3).radius);
  o.realization = 3;
  EXPECT_EQ(chain_realization(o), 3u);
}

TEST(ChainChoices, ReadTheBeadDistributionsAndTheQuasiperiodicChain) {
  ChainChoices o;
  EXPECT_FALSE(bead_distribution(o));
  EXPECT_FALSE(quasiperiodic(o));
  o.disorder = "RDM1", o.types = "4e-3:0.5,3e-3:0.5";
  const auto types = bead_distribution(o);
  ASSERT_TRUE(types);
  EXPECT_EQ(types->kind, BeadDistribution::Kind::types);
  EXPECT_EQ(types->rule, Disorder::rdm1);
  EXPECT_EQ(types->radii, (std::vector<double>{4e-3, 3e-3}));
  o.types.clear(), o.polydisperse = "uniform:3e-3:5e-3";
  EXPECT_EQ(bead_distribution(o)->kind, BeadDistribution::Kind::uniform);
  o.polydisperse.clear(), o.disorder = "A", o.quasi = "cylinders", o.ratio = "1/3", o.modulation = 0.2;
  const auto q = quasiperiodic(o);
  ASSERT_TRUE(q);
  EXPECT_EQ(q->kind, Quasiperiodic::Kind::cylinders);
  EXPECT_DOUBLE_EQ(q->ratio, 1.0 / 3);
  EXPECT_EQ(q->modulation, 0.2);
  std::vector<std::string> warnings;
  EXPECT_TRUE(chain_recipe(o, warnings).as<Quasiperiodic>());
}

TEST(ChainChoices, ErrorsNameTheChoice) {
  const auto with = [](auto set) {
    ChainChoices o;
    set(o);
    return chain_choices_parameter(o);
  };
  EXPECT_EQ(with([](ChainChoices&) {}), "(accepted)");
  EXPECT_EQ(with([](ChainChoices& o) { o.seed = -1; }), "seed");
  EXPECT_EQ(with([](ChainChoices& o) { o.realization = -1; }), "realization");
  EXPECT_EQ(with([](ChainChoices& o) { o.n = 1; }), "N");
  EXPECT_EQ(with([](ChainChoices& o) { o.types = "4e-3"; }), "types");
  EXPECT_EQ(with([](ChainChoices& o) { o.type_masses = "-1:1"; }), "type_masses");
  EXPECT_EQ(with([](ChainChoices& o) { o.polydisperse = "gamma:1:2"; }), "polydisperse");
  EXPECT_EQ(with([](ChainChoices& o) { o.walls = "round"; }), "walls");
}

TEST(ChainChoices, AChainComesFromOneSourceTheSecondIsNamed) {
  ChainChoices o;
  o.types = "4e-3:0.5,3e-3:0.5";
  EXPECT_EQ(chain_choices_parameter(o), "(accepted)");
  o.polydisperse = "uniform:3e-3:4e-3";
  EXPECT_EQ(chain_choices_parameter(o), "polydisperse");
  o.polydisperse.clear(), o.quasi = "s2";
  EXPECT_EQ(chain_choices_parameter(o), "quasi");
  EXPECT_THROW(bead_distribution(o), InvalidInput) << "the rule holds for a caller that reads the parts alone";
  EXPECT_THROW(quasiperiodic(o), InvalidInput);
  o.types.clear(), o.radii = "no-such-file";  // refused before the file is read
  EXPECT_EQ(chain_choices_parameter(o), "quasi");
  o.quasi.clear(), o.config = "no-such-file";
  EXPECT_EQ(chain_choices_parameter(o), "radii");
}

TEST(ChainChoices, ReadARadiiFileWithItsWarnings) {
  const std::string path = testing::scratch_path("chain_choices", "radii.txt");
  std::ofstream(path) << "# radii [m]\n4e-3\n4.76\n3e-3\n";
  ChainChoices o;
  o.radii = path;
  std::vector<std::string> warnings;
  const ChainRecipe r = chain_recipe(o, warnings);
  ASSERT_TRUE(r.as<GivenRadii>());
  EXPECT_EQ(r.as<GivenRadii>()->radii, (std::vector<double>{4e-3, 4.76, 3e-3}));
  EXPECT_EQ(r.as<GivenRadii>()->file, path);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find(path + ":3"), std::string::npos) << warnings[0];
}

}  // namespace
}  // namespace granular
