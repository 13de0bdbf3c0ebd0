// One case, one description: describe() of a kicked-chain case and parse_case() are inverses for
// every option family (plain two types, k types, polydisperse radii, a types or radii file, the
// centred draw, mode kicks, matched β, damping, the tangent map, each integrator), so the output
// JSON, the checkpoint header and the replay command, all made from it, cannot forget a field.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "granular/case/transport_parameters.hpp"
#include "granular/error.hpp"
#include "granular/study/transport_study.hpp"

namespace granular {
namespace {

TransportCase base() {
  TransportCase c;
  c.chain = {.source = TwoTypeDraw{.disorder = Disorder::rdm2, .q = 0.3, .xi = 0.6},
             .R1 = 5e-3,
             .N = 301,
             .F0 = 0.5,
             .seed = 9};
  c.site = 121;
  c.realizations = 7;
  c.profile_realizations = 3;
  c.dynamics.integration.duration = 2e-3;
  c.dynamics.integration.time_step = 0.5e-6;
  c.fit_begin = 1e-3;
  c.fit_end = 2e-3;
  return c;
}

std::vector<std::pair<std::string, TransportCase>> families(const std::string& dir) {
  std::vector<std::pair<std::string, TransportCase>> out{{"plain", base()}};
  const auto add = [&](const std::string& name, auto&& change) {
    TransportCase c = base();
    change(c);
    out.emplace_back(name, c);
  };
  add("types", [](TransportCase& c) {
    c.chain.source =
        BeadDistribution{.radii = {4.76e-3, 3e-3, 2e-3}, .probabilities = {0.5, 0.3, 0.2}, .rule = Disorder::rdm1};
  });
  add("uniform", [](TransportCase& c) {
    c.chain.source = BeadDistribution{.kind = BeadDistribution::Kind::uniform, .low = 2e-3, .high = 5.1e-3};
  });
  add("normal", [](TransportCase& c) {
    c.chain.source =
        BeadDistribution{.kind = BeadDistribution::Kind::normal, .mean = 4e-3, .sd = 3e-4, .minimum = 3.3e-3};
  });
  {
    std::ofstream(dir + "/chain.types") << "1\n2\n2\n1\n1\n2\n";
    std::ofstream(dir + "/chain.radii") << "# radii\n4.76e-3\n3.1e-3\n0.0047\n";
  }
  add("types file", [&](TransportCase& c) {
    c.chain.source = GivenTypes{.types = {1, 2, 2, 1, 1, 2}, .file = dir + "/chain.types"};
    c.site = 3;
  });
  add("radii file", [&](TransportCase& c) {
    c.chain.source = GivenRadii{.radii = {4.76e-3, 3.1e-3, 0.0047}, .file = dir + "/chain.radii"};
    c.site = 2;
  });
  add("centred", [](TransportCase& c) {
    c.chain.draw().centred = true;
    c.site = 151;
  });
  add("mode", [](TransportCase& c) {
    c.kick = Kick::mode;
    c.mode = {.mode = 40, .energy = 2e-9};
  });
  add("mode near", [](TransportCase& c) {
    c.kick = Kick::mode;
    c.mode = {.near_khz = 12.5};
    c.alpha = 3e-8;
  });
  add("velocity", [](TransportCase& c) {
    c.kick = Kick::velocity;
    c.beta = 1.5e-3;
  });
  add("match", [](TransportCase& c) {
    c.kick = Kick::velocity;
    c.beta.reset();  // match
  });
  add("damped", [](TransportCase& c) { c.dynamics.integration.damping = {.time = 1e-3, .kk_gamma = 2e-6}; });
  add("mle", [](TransportCase& c) {
    c.dynamics.integration.lyapunov = {.enabled = true, .renormalize_every = 7, .time_unit = 2e-6};
  });
  for (const char* scheme : {"saba2", "aba864", "srkn14a"})
    add(scheme, [&](TransportCase& c) { c.dynamics.integration.integrator = parse_integrator(scheme); });
  add("reference", [](TransportCase& c) {
    c.dynamics.integration.integrator = parse_integrator("reference");
    c.dynamics.integration.integrator.tolerance.max_step = 2e-8;
  });
  add("no fit", [](TransportCase& c) {  // a window past T: no exponents
    c.fit_end = 3e-3;
    fit_within_duration(c);
  });
  add("window threshold", [](TransportCase& c) { c.dynamics.integration.window.threshold = 1e-20; });
  add("observed otherwise", [](TransportCase& c) {
    c.centre = SpreadCentre::centroid;
    c.dynamics.integration.force_law = ForceLawKind::fpu;
    c.dynamics.spread.samples = 33;
    c.dynamics.spread.sampling = Sampling::uniform;
    c.dynamics.integration.window.enabled = false;  // (a threshold without it is refused: validate)
    c.dynamics.spread.max_energy_error = 1e-6;
    c.dynamics.spread.stop_on_energy_error = false;
    c.criterion = {.kappa = 0.2, .t_start = 1.5e-3};
    c.bootstrap.resamples = 99;
    c.fit_step = 2e-5;
  });
  return out;
}

TEST(CaseDescription, ParseInvertsDescribeForEveryFamily) {
  const std::string dir = std::filesystem::temp_directory_path() / ("granular-case-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const auto& [name, c] : families(dir)) {
    ASSERT_NO_THROW(validate(c)) << name;
    const nlohmann::json described = describe(c);
    const TransportCase back = parse_case(described);
    EXPECT_EQ(describe(back), described) << name;
    // and the chains are the same chains (a file read again, a distribution parsed back)
    for (std::uint64_t r : {0u, 3u}) EXPECT_EQ(back.chain.radii(r), c.chain.radii(r)) << name << " realization " << r;
  }
  std::filesystem::remove_all(dir);
}

// The description is the case: every family differs from the plain case in what it describes
// (a field the description forgot would make two different runs look the same).
TEST(CaseDescription, EveryFamilyIsDescribedApart) {
  const std::string dir = std::filesystem::temp_directory_path() / ("granular-case2-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto all = families(dir);
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j)
      EXPECT_NE(describe(all[i].second), describe(all[j].second)) << all[i].first << " vs " << all[j].first;
  std::filesystem::remove_all(dir);
}

TEST(CaseDescription, BeadDistributionsReadBackExactly) {
  for (const BeadDistribution& d :
       {BeadDistribution{.radii = {0.1 + 0.2, 1.0 / 3}, .probabilities = {1.0 / 3, 2.0 / 3}, .rule = Disorder::rdm2},
        BeadDistribution{.kind = BeadDistribution::Kind::uniform, .low = 1e-3 / 3, .high = 2e-3},
        BeadDistribution{.kind = BeadDistribution::Kind::normal, .mean = 4e-3, .sd = 1e-3 / 7, .minimum = 3e-3}}) {
    const BeadDistribution back = parse_bead_distribution(describe(d));
    EXPECT_EQ(describe(back), describe(d));
    EXPECT_EQ(realization_radii(back, 50, 3, 1), realization_radii(d, 50, 3, 1));
  }
  EXPECT_THROW(parse_bead_distribution("types(A;0.1)"), InvalidInput);
  EXPECT_THROW(parse_bead_distribution("gamma(1,2)"), InvalidInput);
  EXPECT_THROW(parse_bead_distribution("uniform(1,x)"), InvalidInput);
}

TEST(CaseDescription, AMissingKeyIsNamed) {
  for (const Parameter<TransportCase>& p : case_parameters()) {
    if (!p.described) continue;
    nlohmann::json described = describe(base());
    described.erase(p.name);
    try {
      parse_case(described);
      ADD_FAILURE() << "parsed without " << p.name;
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.parameter(), p.name);
      EXPECT_NE(std::string(e.what()).find("not in the case"), std::string::npos) << e.what();
    }
  }
}

// The JSON is the table: one key per described row of case_parameters(), under the row's name
// (the tools' --name, Python's name=), beside the chain's own fields.
TEST(CaseDescription, TheKeysAreTheRowsNames) {
  const TransportCase c = base();
  nlohmann::json chain;
  describe_fields(c.chain, chain);
  std::set<std::string> expected{"profile_realizations"};
  for (const auto& [key, value] : chain.items()) expected.insert(key);
  for (const Parameter<TransportCase>& p : case_parameters())
    if (p.described) {
      EXPECT_TRUE(expected.insert(p.name).second) << p.name << " is also a chain field";
    }
  std::set<std::string> keys;
  const nlohmann::json described = describe(c);
  for (const auto& [key, value] : described.items()) keys.insert(key);
  EXPECT_EQ(keys, expected);
}

// A case file of 0.2.0 spelled its keys with units (dt_s, alpha_m): named as such, not misread.
TEST(CaseDescription, ACaseOfTheFormerKeysIsRefusedNamingTheVersion) {
  nlohmann::json described = describe(base());
  described["dt_s"] = described.at("time_step");
  described.erase("time_step");
  try {
    parse_case(described);
    FAIL() << "a 0.2.0 case parsed";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("0.2.0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace granular
