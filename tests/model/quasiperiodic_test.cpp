// The quasiperiodic chains as recipes (model/quasiperiodic.hpp): what each realization holds,
// phases as realizations, bad input, and the JSON round trip.
#include "granular/model/quasiperiodic.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "granular/model/chain_recipe.hpp"
#include "granular/model/contact_geometry.hpp"

namespace granular {
namespace {

constexpr double pi = std::numbers::pi;

ChainRecipe recipe(Quasiperiodic::Kind kind, double lambda, std::optional<double> phase = std::nullopt) {
  ChainRecipe r{.N = 50, .F0 = 10, .seed = 5};
  r.source = Quasiperiodic{.kind = kind, .modulation = lambda, .phase = phase};
  return r;
}

TEST(Quasiperiodic, S2MassesFollowTheCosine) {
  const Chain c = recipe(Quasiperiodic::Kind::s2, 0.4, 0.3).chain(0);
  const double m = sphere_mass(steel, paper_r1);
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_NEAR(c.mass[i] / (m * (1 + 0.4 * std::cos(2 * pi * golden_mean * static_cast<double>(i + 1) + 0.3))), 1,
                1e-14);
    EXPECT_DOUBLE_EQ(c.contact[i + 1 == c.size() ? i : i + 1], c.contact[1]);  // bulk bonds: one radius
  }
  EXPECT_TRUE(c.onsite.empty());
}

TEST(Quasiperiodic, S1SpringsAreInUnitsOfTheBondStiffness) {
  ChainRecipe r = recipe(Quasiperiodic::Kind::s1, 0.5, 1.0);
  r.as<Quasiperiodic>()->k0 = 3;
  const Chain c = r.chain(0);
  const double K = linear_stiffness(c.contact[1], c.precompression);
  ASSERT_EQ(c.onsite.size(), c.size());
  for (std::size_t i = 0; i < c.size(); ++i)
    EXPECT_NEAR(c.onsite[i] / (3 * K * (1 + 0.5 * std::cos(2 * pi * golden_mean * static_cast<double>(i + 1) + 1))), 1,
                1e-13);
}

TEST(Quasiperiodic, CylinderBondsTakeTheirAngles) {
  ChainRecipe r = recipe(Quasiperiodic::Kind::cylinders, 0.3, 0.2);
  r.as<Quasiperiodic>()->angle = 50;
  const Chain c = r.chain(0);
  ASSERT_EQ(c.bonds(), c.size() + 1);
  for (std::size_t k = 0; k < c.bonds(); ++k) {
    const double angle = 50 * (1 + 0.3 * std::cos(2 * pi * golden_mean * static_cast<double>(k) + 0.2));
    EXPECT_NEAR(c.contact[k] / hertz_coefficient(steel, steel, crossed_cylinders(paper_r1, angle * pi / 180)), 1, 1e-14);
  }
  EXPECT_NEAR(c.mass[0], steel.density * pi * paper_r1 * paper_r1 * 2 * paper_r1, 1e-15);
}

TEST(Quasiperiodic, RealizationsArePhasesDrawnFromTheSeed) {
  const ChainRecipe r = recipe(Quasiperiodic::Kind::s2, 0.5);
  const double p0 = quasiperiodic_phase(*r.as<Quasiperiodic>(), r.seed, 0),
               p1 = quasiperiodic_phase(*r.as<Quasiperiodic>(), r.seed, 1);
  EXPECT_NE(p0, p1);
  for (double p : {p0, p1}) EXPECT_TRUE(p >= 0 && p < 2 * pi);
  EXPECT_EQ(p0, quasiperiodic_phase(*r.as<Quasiperiodic>(), r.seed, 0));  // a pure function of (seed, r)
  ChainRecipe given = r;
  given.as<Quasiperiodic>()->phase = p1;
  EXPECT_EQ(given.chain(0).mass, r.chain(1).mass);
  // The phase is uniform: the mean of cos φ over many realizations is near 0.
  double mean = 0;
  for (std::uint64_t k = 0; k < 4000; ++k) mean += std::cos(quasiperiodic_phase(*r.as<Quasiperiodic>(), 9, k)) / 4000;
  EXPECT_LT(std::fabs(mean), 0.05);
}

TEST(Quasiperiodic, BadInputNamesTheField) {
  const auto field = [](ChainRecipe r) {
    try {
      validate(r);
    } catch (const InvalidInput& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  auto r = recipe(Quasiperiodic::Kind::s2, 1.0);
  EXPECT_EQ(field(r), "modulation");
  r.as<Quasiperiodic>()->modulation = 0.5;
  EXPECT_EQ(field(r), "none");
  r.as<Quasiperiodic>()->ratio = 0;
  EXPECT_EQ(field(r), "ratio");
  r.as<Quasiperiodic>()->ratio = -1;
  EXPECT_EQ(field(r), "ratio");
  r = recipe(Quasiperiodic::Kind::cylinders, 0.5);
  r.as<Quasiperiodic>()->angle = 150;  // 150 × 1.5 > 180
  EXPECT_EQ(field(r), "modulation");
  r.as<Quasiperiodic>()->angle = 0;
  EXPECT_EQ(field(r), "angle");
  r = recipe(Quasiperiodic::Kind::s1, -1.2);
  EXPECT_EQ(field(r), "modulation");
  r.as<Quasiperiodic>()->modulation = 0.2;
  r.as<Quasiperiodic>()->k0 = 0;
  EXPECT_EQ(field(r), "k0");
  r.as<Quasiperiodic>()->k0 = 1;
  r.F0 = 0;
  EXPECT_EQ(field(r), "F0");
  EXPECT_THROW(parse_ratio("0/3"), InvalidInput);
  EXPECT_THROW(parse_ratio("x"), InvalidInput);
  EXPECT_THROW(parse_quasi_kind("s3"), InvalidInput);
  EXPECT_DOUBLE_EQ(parse_ratio("2/5"), 0.4);
  EXPECT_DOUBLE_EQ(parse_ratio("golden"), (std::sqrt(5.0) - 1) / 2);
}

// The cylinder chain's contact ellipse (issue 42, item 7): its semi-axis at the static overlap
// against R, at the angle of any phase nearest parallel; warned above 0.1 R, refused from 0.5 R
// (docs/physics.md). The paper's beads at F0 = 10 N: 0.028 R at 45°, about 0.1 R at 10°, 0.5 R
// near 1°, R near 0.45° (α0 = 45°, λ = 0.99).
TEST(Quasiperiodic, CylinderContactEllipseStaysSmallAgainstTheCylinders) {
  const auto extent = [](double angle, double lambda, double F0 = 10) {
    const Quasiperiodic q{.kind = Quasiperiodic::Kind::cylinders, .modulation = lambda, .angle = angle};
    return cylinder_contact_extent(q, paper_r1, F0, steel);
  };
  const auto field = [](ChainRecipe r) {
    try {
      validate(r);
    } catch (const InvalidInput& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  const CylinderContactExtent at45 = extent(45, 0);
  EXPECT_NEAR(at45.semi_axis_over_radius, 0.028, 0.002);
  EXPECT_EQ(at45.angle_deg, 45);
  // The end of the range nearest parallel counts, at either end (135° is 45° from parallel).
  EXPECT_NEAR(extent(45, 0.5).angle_deg, 22.5, 1e-12);
  EXPECT_NEAR(extent(80, 0.6).angle_deg, 32, 1e-12);
  EXPECT_NEAR(extent(100, 0.75).angle_deg, 175, 1e-12);
  EXPECT_NEAR(extent(45, 0.99).semi_axis_over_radius, 0.96, 0.03);
  EXPECT_GT(extent(45, 0.5, 100).semi_axis_over_radius, extent(45, 0.5, 10).semi_axis_over_radius);
  EXPECT_EQ(extent(45, 0.5, 0).semi_axis_over_radius, 0);  // no overlap, no ellipse
  std::printf("a/R at F0 = 10 N: 45 deg %.4f, 10 deg %.4f, 1 deg %.4f, 0.45 deg %.4f\n", at45.semi_axis_over_radius,
              extent(10, 0).semi_axis_over_radius, extent(1, 0).semi_axis_over_radius,
              extent(0.45, 0).semi_axis_over_radius);

  auto r = recipe(Quasiperiodic::Kind::cylinders, 0.5);
  EXPECT_EQ(check_cylinder_contacts(*r.as<Quasiperiodic>(), paper_r1, r.F0, steel), "");  // 22.5°: 0.05 R
  r.as<Quasiperiodic>()->modulation = 0.9;  // 4.5°: warned, naming the modulation
  EXPECT_EQ(field(r), "none");
  const std::string warning =
      check_cylinder_contacts(*r.as<Quasiperiodic>(), paper_r1, r.F0, steel, "--angle", "--modulation");
  EXPECT_EQ(warning.rfind("--modulation 0.9: at 4.5 degrees", 0), 0u) << warning;
  r.as<Quasiperiodic>()->modulation = 0.99;  // 0.45°: refused, naming the modulation
  EXPECT_EQ(field(r), "modulation");
  EXPECT_THROW(r.chain(0), InvalidInput);
  r.as<Quasiperiodic>()->modulation = 0;
  r.as<Quasiperiodic>()->angle = 0.5;  // the angle alone
  EXPECT_EQ(field(r), "angle");
  r.as<Quasiperiodic>()->angle = 179.5;  // as near parallel the other way
  EXPECT_EQ(field(r), "angle");
  r.as<Quasiperiodic>()->angle = 5;  // warned, naming the angle
  EXPECT_EQ(field(r), "none");
  EXPECT_EQ(check_cylinder_contacts(*r.as<Quasiperiodic>(), paper_r1, r.F0, steel).rfind("angle 5: at 5 degrees", 0),
            0u);
  // Quasiperiodic chains of spheres have no such limit.
  EXPECT_EQ(check_cylinder_contacts({.kind = Quasiperiodic::Kind::s2, .modulation = 0.99}, paper_r1, 10, steel), "");
}

TEST(Quasiperiodic, DescriptionRoundTrips) {
  for (auto kind : {Quasiperiodic::Kind::s1, Quasiperiodic::Kind::s2, Quasiperiodic::Kind::cylinders})
    for (std::optional<double> phase : {std::optional<double>{}, std::optional<double>{0.7}}) {
      ChainRecipe r = recipe(kind, 0.35, phase);
      r.as<Quasiperiodic>()->ratio = 0.4;
      r.as<Quasiperiodic>()->angle = 60;
      r.as<Quasiperiodic>()->k0 = 2.5;
      nlohmann::json f;
      describe_fields(r, f);
      const ChainRecipe back = parse_recipe_fields(nlohmann::json::parse(f.dump()));
      ASSERT_TRUE(back.as<Quasiperiodic>());
      EXPECT_EQ(back.chain(3).mass, r.chain(3).mass);
      EXPECT_EQ(back.chain(3).contact, r.chain(3).contact);
      EXPECT_EQ(back.chain(3).onsite, r.chain(3).onsite);
      EXPECT_EQ(describe(back, 3), describe(r, 3));
    }
}

TEST(Quasiperiodic, LocalChainsBoundEveryRealization) {
  // The three-bead chains of the time-step rule hold the lightest bead and the stiffest bond of
  // any phase.
  for (auto kind : {Quasiperiodic::Kind::s2, Quasiperiodic::Kind::cylinders}) {
    const ChainRecipe r = recipe(kind, 0.6);
    double lightest = INFINITY, stiffest = 0;
    for (const Chain& c : quasiperiodic_local_chains(*r.as<Quasiperiodic>(), r.R1, r.F0, r.material)) {
      for (double m : c.mass) lightest = std::fmin(lightest, m);
      for (double a : c.contact) stiffest = std::fmax(stiffest, a);
    }
    for (std::uint64_t k = 0; k < 20; ++k) {
      const Chain c = r.chain(k);
      for (double m : c.mass) EXPECT_GE(m, lightest * (1 - 1e-14));
      for (double a : c.contact) EXPECT_LE(a, stiffest * (1 + 1e-14));
    }
  }
}

}  // namespace
}  // namespace granular
