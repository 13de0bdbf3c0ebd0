// A library message told in a front end's words: only parameter names change.
#include "granular/parameter_names.hpp"

#include <gtest/gtest.h>

namespace granular {
namespace {

TEST(ParameterNames, RenamesOnlyWordsWithAnUnderscore) {
  const auto flag = [](const std::string& word) { return word == "unknown_thing" ? "" : "--" + word; };
  EXPECT_EQ(rename_parameters("max_energy_error 0.1 passed at t_1 (time_step 1e-6); N too small", flag),
            "--max_energy_error 0.1 passed at --t_1 (--time_step 1e-6); N too small");
  EXPECT_EQ(rename_parameters("unknown_thing stays", flag), "unknown_thing stays");
  EXPECT_EQ(rename_parameters("", flag), "");
  EXPECT_EQ(rename_parameters("Kick_size: upper-case words are not names", flag),
            "K--ick_size: upper-case words are not names");
}

TEST(ParameterNames, FrontEndsSayThePhysicsSymbols) {
  EXPECT_EQ(front_end_word("precompression"), "F0");
  EXPECT_EQ(front_end_word("n"), "N");
  EXPECT_EQ(front_end_word("r1"), "R1");
  EXPECT_EQ(front_end_word("time_step"), "dt");
  EXPECT_EQ(front_end_word("duration"), "T");
  EXPECT_EQ(front_end_word("near_khz"), "near");
  EXPECT_EQ(front_end_word("max_energy_error"), "max_energy_error");  // its own word
  EXPECT_EQ(front_end_word(""), "");
}

}  // namespace
}  // namespace granular
