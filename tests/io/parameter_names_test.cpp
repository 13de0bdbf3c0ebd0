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

}  // namespace
}  // namespace granular
