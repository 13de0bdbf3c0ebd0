// A replay command is printed only when it reads back as the very case that failed.
#include "granular/study/case_replay.hpp"

#include <stdexcept>

#include <gtest/gtest.h>

namespace granular {
namespace {

TransportCase ensemble_case() {
  TransportCase c;
  c.chain.N = 11;
  c.site = 5;
  c.dynamics.integration.duration = 1e-4;
  c.fit = false;
  c.realizations = 5;
  c.profile_realizations = 5;
  return c;
}

TEST(CaseReplay, ArgumentsThatReadBackAsTheCaseRunAloneArePrinted) {
  const TransportCase c = ensemble_case();
  const CaseSpelling exact{[](const TransportCase&, std::uint64_t r) {
                             return std::vector<std::string>{"--r", std::to_string(r)};
                           },
                           [&](const std::vector<std::string>&) {
                             TransportCase alone = c;
                             alone.realizations = 1, alone.profile_realizations = 0;
                             return alone;
                           }};
  const auto arguments = replay_arguments(c, 3, exact);
  ASSERT_TRUE(arguments);
  EXPECT_EQ(*arguments, (std::vector<std::string>{"--r", "3"}));
}

TEST(CaseReplay, ACaseTheArgumentsCannotSpellGetsTheFieldsThatDiffer) {
  const TransportCase c = ensemble_case();
  TransportCase other = c;
  other.realizations = 1, other.profile_realizations = 0;
  other.dynamics.integration.duration = 2e-4;
  const std::string expected = differing_fields(c, other);
  EXPECT_FALSE(expected.empty());
  const CaseSpelling lossy{[](const TransportCase&, std::uint64_t) { return std::vector<std::string>{}; },
                           [&](const std::vector<std::string>&) { return other; }};
  std::string why;
  EXPECT_FALSE(replay_arguments(c, 0, lossy, &why));
  TransportCase alone = c;
  alone.realizations = 1, alone.profile_realizations = 0;
  EXPECT_EQ(why, differing_fields(alone, other));
  EXPECT_EQ(differing_fields(alone, alone), "");

  const CaseSpelling unreadable{[](const TransportCase&, std::uint64_t) { return std::vector<std::string>{}; },
                                [](const std::vector<std::string>&) -> TransportCase {
                                  throw std::invalid_argument("--x: no such flag");
                                }};
  EXPECT_FALSE(replay_arguments(c, 0, unreadable, &why));
  EXPECT_EQ(why, "the flags do not read back: --x: no such flag");
}

}  // namespace
}  // namespace granular
