// The `klein-gordon` job's case (klein_gordon/klein_gordon_case.hpp): its samples' rule, its JSON round
// trip through its table, and refusals naming the row.
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "granular/klein_gordon/klein_gordon_case.hpp"
#include "granular/parameter_json.hpp"

namespace granular {
namespace {

TEST(KleinGordonCase, SamplesAreLogSpacedFromOneStepToT) {
  KleinGordonCase c;
  c.duration = 1000;  // n = 5000 steps of τ = 0.2
  c.samples = 5;
  EXPECT_EQ(sample_steps(c), (std::vector<std::uint64_t>{1, 8, 71, 595, 5000}));  // 5000^(k/4), rounded
  c.samples = 1;
  EXPECT_EQ(sample_steps(c), (std::vector<std::uint64_t>{5000}));
  c.duration = 2;  // n = 10: 100 samples round to each step once
  c.samples = 100;
  EXPECT_EQ(sample_steps(c), (std::vector<std::uint64_t>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
  c.duration = 1e4;
  c.samples = 50;
  const std::vector<std::uint64_t> steps = run_config(c).sample_steps;
  EXPECT_EQ(steps.front(), 1U);
  EXPECT_EQ(steps.back(), 50000U);
  for (std::size_t k = 1; k < steps.size(); ++k) EXPECT_LT(steps[k - 1], steps[k]);
}

TEST(KleinGordonCase, JsonRoundTripGivesTheSameCase) {
  KleinGordonCase c;
  c.run.chain = {.N = 333, .W = 2.5, .seed = 12345678901234ULL};
  c.run.energy = 0.05;
  c.run.block = 21;
  c.run.time_step = 0.1;
  c.run.mle = false;
  c.duration = 123.4;
  c.samples = 7;
  c.realizations = 3;
  c.threads = 2;
  c.fit = {10, 100};
  c.run.energy_map = true;
  const nlohmann::json described = describe_rows(c, klein_gordon_parameters());
  EXPECT_EQ(described.size(), klein_gordon_parameters().size());  // every row has a key
  const KleinGordonCase back = parse_rows(nlohmann::json::parse(described.dump()), klein_gordon_parameters());
  EXPECT_EQ(describe_rows(back, klein_gordon_parameters()), described);
  EXPECT_EQ(back.run.chain.seed, c.run.chain.seed);
  EXPECT_EQ(back.run.time_step, c.run.time_step);
  EXPECT_EQ(back.duration, c.duration);
  EXPECT_FALSE(back.run.mle);
  EXPECT_EQ(back.fit, c.fit);
  EXPECT_TRUE(back.run.energy_map);
  EXPECT_EQ(described.at("fit"), nlohmann::json({10.0, 100.0}));
  EXPECT_EQ(sample_steps(back), sample_steps(c));
}

TEST(KleinGordonCase, RefusalsNameTheRow) {
  const std::vector<std::pair<std::function<void(KleinGordonCase&)>, std::string>> cases = {
      {[](KleinGordonCase& c) { c.run.chain.N = 1; }, "N"},
      {[](KleinGordonCase& c) { c.run.chain.N = 100000001; }, "N"},
      {[](KleinGordonCase& c) { c.run.chain.W = 0; }, "W"},
      {[](KleinGordonCase& c) { c.run.energy = -1; }, "energy"},
      {[](KleinGordonCase& c) { c.run.block = 1001; }, "block"},
      {[](KleinGordonCase& c) { c.run.time_step = 0; }, "time_step"},
      {[](KleinGordonCase& c) { c.duration = 0.1; }, "duration"},  // below one step
      {[](KleinGordonCase& c) { c.duration = 1e14; }, "duration"},
      {[](KleinGordonCase& c) { c.samples = 0; }, "samples"},
      {[](KleinGordonCase& c) { c.realizations = 0; }, "realizations"},
      {[](KleinGordonCase& c) { c.realizations = 1000001; }, "realizations"},
      {[](KleinGordonCase& c) { c.threads = -1; }, "threads"},
      // T = 1e4 at τ = 0.2 with 50 log-spaced samples: a window inside (0, T] with 3 of them ([100, 110]: none)
      {[](KleinGordonCase& c) {
         c.fit = {0, 100};
       },
       "fit"},
      {[](KleinGordonCase& c) {
         c.fit = {100, 10};
       },
       "fit"},
      {[](KleinGordonCase& c) {
         c.fit = {100, 100};
       },
       "fit"},
      {[](KleinGordonCase& c) {
         c.fit = {100, 2e4};
       },
       "fit"},
      {[](KleinGordonCase& c) {
         c.fit = {100, 110};
       },
       "fit"},
      {[](KleinGordonCase& c) { c.fit = {100}; }, "fit"},
      {[](KleinGordonCase& c) {
         c.fit = {1, 2, 3};
       },
       "fit"},
      {[](KleinGordonCase& c) {
         c.fit = {NAN, 100};
       },
       "fit"},
  };
  for (const auto& [change, name] : cases) {
    KleinGordonCase c;
    change(c);
    try {
      validate(c);
      ADD_FAILURE() << name << " taken";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.parameter(), name) << e.what();
    }
  }
  EXPECT_NO_THROW(validate(KleinGordonCase{}));
  KleinGordonCase whole;
  whole.fit = {0.2, 1e4};  // the first sample to the last
  EXPECT_NO_THROW(validate(whole));
}

}  // namespace
}  // namespace granular
