// The typed forms of a bead distribution read back as what they spell, and say what is wrong.
#include "granular/io/bead_distribution_syntax.hpp"

#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "granular/model/material.hpp"

namespace granular {
namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(BeadDistributionSyntax, TypesReadBackExactlyFromTheirSpelling) {
  const BeadDistribution d = parse_bead_types("4.76e-3:0.5,3e-3:0.3,2e-3:0.2", false, Disorder::rdm1, "--types");
  EXPECT_EQ(d.kind, BeadDistribution::Kind::types);
  EXPECT_EQ(d.radii, (std::vector<double>{4.76e-3, 3e-3, 2e-3}));
  EXPECT_EQ(d.probabilities, (std::vector<double>{0.5, 0.3, 0.2}));
  EXPECT_EQ(d.rule, Disorder::rdm1);
  EXPECT_EQ(spell(d), "0.00476:0.5,0.003:0.3,0.002:0.2");
  const BeadDistribution again = parse_bead_types(spell(d), false, Disorder::rdm1, "--types");
  EXPECT_EQ(describe(again), describe(d));
}

TEST(BeadDistributionSyntax, MassesAreThoseOfSteelSpheres) {
  const double m = 1e-3;
  const BeadDistribution d = parse_bead_types("1e-3:1", true, Disorder::anderson, "--type-masses");
  ASSERT_EQ(d.radii.size(), 1u);
  EXPECT_EQ(d.radii[0], sphere_radius(steel, m));
}

TEST(BeadDistributionSyntax, PolydisperseFormsReadBackExactly) {
  for (const std::string text : {"uniform:0.003:0.005", "normal:0.004:5e-04:0.003"}) {
    const BeadDistribution d = parse_polydisperse(text, "--polydisperse");
    EXPECT_TRUE(d.radii.empty());
    EXPECT_EQ(spell(d), text);
  }
  EXPECT_EQ(parse_polydisperse("normal:4e-3:5e-4:3e-3", "p").kind, BeadDistribution::Kind::normal);
}

TEST(BeadDistributionSyntax, MessagesNameWhatTheUserTyped) {
  EXPECT_EQ(message_of([] { parse_bead_types("4e-3", false, Disorder::anderson, "--types"); }),
            "--types '4e-3': expected RADIUS:PROBABILITY");
  EXPECT_EQ(message_of([] { parse_bead_types("1e-3:1", true, Disorder::anderson, "--type-masses"); }), "(accepted)");
  EXPECT_EQ(message_of([] { parse_bead_types("-1:1", true, Disorder::anderson, "--type-masses"); }),
            "--type-masses '-1:1': mass must be finite and > 0");
  EXPECT_EQ(message_of([] { parse_polydisperse("gamma:1:2", "--polydisperse"); }),
            "--polydisperse 'gamma:1:2': expected uniform:LO:HI or normal:MEAN:SD:MIN (metres)");
  EXPECT_EQ(message_of([] {
              parse_polydisperse("uniform:5e-3:3e-3", "--polydisperse");
            }).rfind("--polydisperse 'uniform:5e-3:3e-3': ", 0),
            0u);
}

}  // namespace
}  // namespace granular
