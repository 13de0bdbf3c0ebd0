// The chain recipe's bead source is one alternative of ChainSource: each kind names itself, says
// whether realizations differ and whether they are two bead types, and (drawn kinds) reads back
// from a case's fields as the same chains.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "granular/error.hpp"
#include "granular/model/chain_recipe.hpp"

namespace granular {
namespace {

struct SourceKind {
  ChainSource source;
  std::string name;
  bool drawn, typed, streamed;
};

std::vector<SourceKind> every_source_kind() {
  return {{TwoTypeDraw{.disorder = Disorder::rdm2, .q = 0.3, .xi = 0.6}, "RDM2", true, true, true},
          {TwoTypeDraw{.disorder = Disorder::anderson, .centred = true}, "A", true, true, false},
          {BeadDistribution{.radii = {4e-3, 3e-3}, .probabilities = {0.4, 0.6}}, "types", true, false, false},
          {BeadDistribution{.kind = BeadDistribution::Kind::uniform, .low = 3e-3, .high = 5e-3}, "polydisperse", true,
           false, false},
          {GivenTypes{.types = Configuration(30, 1), .xi = 0.7}, "config", false, true, false},
          {GivenRadii{.radii = std::vector<double>(30, 4e-3)}, "radii", false, false, false},
          {Quasiperiodic{.kind = Quasiperiodic::Kind::s2, .modulation = 0.4}, "quasi-s2", true, false, false}};
}

TEST(ChainSource, EveryKindNamesItselfAndSaysWhatItIs) {
  const auto kinds = every_source_kind();
  ASSERT_EQ(kinds.size(), std::variant_size_v<ChainSource> + 2);  // two draws, two distributions
  for (const SourceKind& k : kinds) {
    const ChainRecipe r{.source = k.source, .N = 30, .F0 = 2, .seed = 5};
    EXPECT_NO_THROW(validate(r)) << k.name;
    EXPECT_EQ(source_name(r), k.name);
    EXPECT_EQ(r.drawn(), k.drawn) << k.name;
    EXPECT_EQ(r.typed(), k.typed) << k.name;
    EXPECT_EQ(r.streamed(), k.streamed) << k.name;
    EXPECT_EQ(r.size(), 30u) << k.name;
    EXPECT_EQ(r.chain(0).radius.size(), 30u) << k.name;
    EXPECT_EQ(r.types(0).empty(), !k.typed) << k.name;
    EXPECT_EQ(r.xi() == r.xi(), k.typed) << k.name << ": ξ only for two types";
    if (k.drawn) {
      EXPECT_NE(r.chain(0).mass, r.chain(1).mass) << k.name << ": realizations differ";
    }
  }
}

TEST(ChainSource, DrawnKindsReadBackFromACaseAsTheSameChains) {
  for (const SourceKind& k : every_source_kind()) {
    if (!k.drawn) continue;  // given beads are read back from their file (configuration_file_test)
    const ChainRecipe r{.source = k.source, .N = 30, .F0 = 2, .seed = 5};
    nlohmann::json fields;
    describe_fields(r, fields);
    const ChainRecipe back = parse_recipe_fields(fields);
    EXPECT_EQ(back.source.index(), r.source.index()) << k.name;
    EXPECT_EQ(source_name(back), k.name);
    EXPECT_EQ(back.chain(3).mass, r.chain(3).mass) << k.name;
  }
}

TEST(ChainSource, TheDrawIsRefusedForAnotherSourceByName) {
  ChainRecipe r{.source = GivenRadii{.radii = {4e-3, 3e-3}}};
  try {
    r.draw();
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "chain");
  }
  r.source = TwoTypeDraw{};
  r.draw().q = 0.25;
  EXPECT_EQ(std::get<TwoTypeDraw>(r.source).q, 0.25);
}

}  // namespace
}  // namespace granular
