// Chains beyond two types: k types with probabilities, polydisperse radii,
// and the two-type case reproducing the paper's disorder kinds bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "granular/error.hpp"
#include "granular/model/bead_distribution.hpp"
#include "granular/model/configuration_file.hpp"
#include "granular/model/disorder.hpp"
#include "granular/model/material.hpp"

namespace granular {
namespace {

TEST(BeadDistribution, TypeFractionsOverAMillionBeadsMatchTheProbabilities) {
  const BeadDistribution three{.radii = {4.76e-3, 3e-3, 2e-3}, .probabilities = {0.5, 0.3, 0.2}};
  for (Disorder rule : {Disorder::anderson, Disorder::rdm1}) {
    BeadDistribution d = three;
    d.rule = rule;
    const std::size_t n = 1000000;
    const std::vector<double> radii = realization_radii(d, n, 5, 0);
    // Draws: beads (A) or dimers (RDM1, both beads one type); the fraction's σ = sqrt(p(1−p)/draws).
    const double draws = rule == Disorder::anderson ? double(n) : double(n) / 2;
    for (std::size_t t = 0; t < 3; ++t) {
      const double fraction = double(std::count(radii.begin(), radii.end(), d.radii[t])) / double(n);
      const double p = d.probabilities[t], sigma = std::sqrt(p * (1 - p) / draws);
      EXPECT_LT(std::fabs(fraction - p), 3 * sigma) << to_string(rule) << " type " << t + 1 << ": " << fraction;
    }
    if (rule == Disorder::rdm1) {
      for (std::size_t i = 0; i + 1 < n; i += 2) ASSERT_EQ(radii[i], radii[i + 1]) << "dimer at " << i;
    }
  }
}

TEST(BeadDistribution, TwoTypesReproduceThePapersChainsBitForBit) {
  for (Disorder rule : {Disorder::anderson, Disorder::rdm1, Disorder::rdm2})
    for (double q : {0.0, 0.2, 0.5, 0.8, 1.0})
      for (std::size_t n : {100, 101})
        for (std::uint64_t realization : {0, 7}) {
          const double r1 = 4.76e-3, xi = 0.37;
          const BeadDistribution d{.radii = {r1, xi * r1}, .probabilities = {q, 1 - q}, .rule = rule};
          EXPECT_EQ(realization_radii(d, n, 3, realization),
                    radii_of(realization_configuration(rule, q, n, 3, realization), r1, xi))
              << to_string(rule) << " q " << q << " N " << n;
        }
}

TEST(BeadDistribution, PolydisperseRadiiFollowTheirDistributions) {
  const std::size_t n = 200000;
  const BeadDistribution uniform{.kind = BeadDistribution::Kind::uniform, .low = 2e-3, .high = 5e-3};
  const auto u = realization_radii(uniform, n, 1, 0);
  EXPECT_GE(*std::min_element(u.begin(), u.end()), 2e-3);
  EXPECT_LE(*std::max_element(u.begin(), u.end()), 5e-3);
  double mean = 0;
  for (double r : u) mean += r / double(n);
  EXPECT_NEAR(mean, 3.5e-3, 3 * 3e-3 / std::sqrt(12.0 * double(n)));
  // Normal (4 mm, 1 mm) truncated at 3.5 mm: mean μ + σ φ(a)/Q(a), a = (3.5 − 4)/1.
  const BeadDistribution normal{.kind = BeadDistribution::Kind::normal, .mean = 4e-3, .sd = 1e-3, .minimum = 3.5e-3};
  const auto g = realization_radii(normal, n, 1, 0);
  EXPECT_GE(*std::min_element(g.begin(), g.end()), 3.5e-3);
  const double a = -0.5, phi = std::exp(-a * a / 2) / std::sqrt(2 * std::numbers::pi);
  const double q = 0.5 * std::erfc(a / std::sqrt(2.0));
  const double expected = 4e-3 + 1e-3 * phi / q;
  const double variance = 1e-6 * (1 + a * phi / q - (phi / q) * (phi / q));
  mean = 0;
  for (double r : g) mean += r / double(n);
  EXPECT_NEAR(mean, expected, 3 * std::sqrt(variance / double(n)));
  // A realization is a pure function of (seed, realization): another realization differs.
  EXPECT_EQ(realization_radii(normal, 100, 1, 3), realization_radii(normal, 100, 1, 3));
  EXPECT_NE(realization_radii(normal, 100, 1, 3), realization_radii(normal, 100, 1, 4));
}

TEST(BeadDistribution, BadDistributionsNameTheirField) {
  const auto field = [](const BeadDistribution& d) {
    try {
      validate(d);
    } catch (const InvalidInput& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  EXPECT_EQ(field({.radii = {1e-3, 2e-3}, .probabilities = {0.5, 0.6}}), "probabilities");
  EXPECT_EQ(field({.radii = {1e-3, 2e-3}, .probabilities = {0.5}}), "probabilities");
  EXPECT_EQ(field({.radii = {1e-3, -2e-3}, .probabilities = {0.5, 0.5}}), "radii");
  EXPECT_EQ(field({.radii = {1e-3, 2e-3, 3e-3}, .probabilities = {0.5, 0.3, 0.2}, .rule = Disorder::rdm2}), "rule");
  EXPECT_EQ(field({.kind = BeadDistribution::Kind::uniform, .low = 3e-3, .high = 2e-3}), "high");
  EXPECT_EQ(field({.kind = BeadDistribution::Kind::normal, .mean = 4e-3, .sd = 0, .minimum = 1e-3}), "sd");
  EXPECT_EQ(field({.radii = {1e-3, 2e-3}, .probabilities = {0.5, 0.5}}), "none");
}

TEST(BeadDistribution, MassesGiveTheRadiiOfTheirSpheres) {
  for (double r : {1e-4, 2.38e-3, 4.76e-3, 0.05})
    EXPECT_NEAR(sphere_radius(steel, sphere_mass(steel, r)), r, 1e-15 * r);
  EXPECT_NEAR(sphere_mass(steel, 4.76e-3), 3.626368e-3, 1e-9);  // docs/physics.md, "The linear spectrum": m1
}

TEST(RadiiFile, ImplausibleRadiiAreWarnedWithFileAndLine) {
  std::vector<std::string> warnings;
  const auto radii = parse_radii_text("4.76e-3\n# comment\n4.76\n5e-5\n0.1\n", "chain.radii", &warnings);
  ASSERT_EQ(radii.size(), 4u);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("chain.radii:3"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("chain.radii:4"), std::string::npos) << warnings[1];
}

}  // namespace
}  // namespace granular
