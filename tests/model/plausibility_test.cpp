// Unit-slip warnings: which radii and frequencies draw one, and the frequency bound they use
// checked against the true highest frequency of random chains (LAPACK eigenvalues).
#include "granular/model/plausibility.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"

namespace granular {
namespace {

const RadiusNames tool_names{"--R1", "--types", "--radii"};

TEST(RadiusWarnings, MillimetresTypedAsMetresAreNamed) {
  ChainRecipe paper;
  EXPECT_TRUE(radius_warnings(paper, tool_names).empty());
  ChainRecipe slip;
  slip.R1 = 4.76;
  const auto w = radius_warnings(slip, tool_names);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("--R1: radius 4.76 m", 0), 0u) << w[0];
  ChainRecipe tiny;
  tiny.draw().xi = 0.01;  // ξ R1 = 47.6 µm: below the range though R1 is right
  ASSERT_EQ(radius_warnings(tiny, tool_names).size(), 1u);
  EXPECT_NE(radius_warnings(tiny, tool_names)[0].find("--R1 times xi"), std::string::npos);
}

TEST(RadiusWarnings, AGivenListNamesItsFirstOffenderAndCountsTheRest) {
  ChainRecipe list;
  list.source = GivenRadii{.radii = {4.76e-3, 4.76, 2e-3, 3.0}};
  auto w = radius_warnings(list, tool_names);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("--radii[1]: radius 4.76 m"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("(and 1 more)"), std::string::npos) << w[0];
  std::get<GivenRadii>(list.source).file = "chain.radii";  // a file: read_radii_file warned per line already
  EXPECT_TRUE(radius_warnings(list, tool_names).empty());
}

TEST(RadiusWarnings, DistributionsWarnForTheRadiiTyped) {
  ChainRecipe types;
  types.source = parse_bead_distribution("types(A;0.00476:0.5,4.76:0.5)");
  ASSERT_EQ(radius_warnings(types, tool_names).size(), 1u);
  EXPECT_EQ(radius_warnings(types, tool_names)[0].rfind("--types: radius 4.76 m", 0), 0u);
}

TEST(FrequencyBound, HoldsEveryFrequencyOfRandomChainsAndIsNotLoose) {
  for (const Disorder rule : {Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2})
    for (const double xi : {0.1, 0.5, 1.0})
      for (const double f0 : {0.01, 10.0}) {
        ChainRecipe r{.source = TwoTypeDraw{.disorder = rule, .q = 0.5, .xi = xi}, .N = 200, .F0 = f0, .seed = 5};
        const double bound = highest_frequency_bound_khz(r);
        for (std::uint64_t k = 0; k < 3; ++k) {
          const Spectrum s = spectrum(dynamical_matrix(r.chain(k)));
          const double top = *std::max_element(s.freq_khz.begin(), s.freq_khz.end());
          EXPECT_LE(top, bound) << to_string(rule) << " xi " << xi << " F0 " << f0;
          EXPECT_GT(top, bound / 4) << to_string(rule) << " xi " << xi << " F0 " << f0;
        }
      }
  ChainRecipe vacuum;
  vacuum.F0 = 0;
  EXPECT_EQ(highest_frequency_bound_khz(vacuum), 0.0);
}

TEST(FrequencyWarning, OnlyAboveTheBound) {
  EXPECT_EQ(frequency_warning("--near", 15, 40), "");
  EXPECT_EQ(frequency_warning("--near", 15000, 0), "");  // no linear frequencies to compare with
  const std::string w = frequency_warning("--near", 15000, 37.2);
  EXPECT_EQ(w.rfind("--near 15000: above every frequency of this chain (all below 38 kHz)", 0), 0u) << w;
}

}  // namespace
}  // namespace granular
