// "Did you mean": the nearest known word, never one too far from what was typed.
#include "granular/io/nearest_word.hpp"

#include <gtest/gtest.h>

namespace granular {
namespace {

TEST(NearestWord, CountsEditsIgnoringCase) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("--dt", ""), 4u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("--f0", "--F0"), 0u);
  EXPECT_EQ(edit_distance("--relizations", "--realizations"), 1u);
}

TEST(NearestWord, SuggestsTheFirstNearestWithinReach) {
  const std::vector<std::string> flags{"--seed", "--sed", "--realizations", "--N"};
  EXPECT_EQ(nearest_word("--relizations", flags), "--realizations");
  EXPECT_EQ(nearest_word("--seeds", flags), "--seed");  // 1 edit from --seed, 2 from --sed
  EXPECT_EQ(nearest_word("--sd", flags), "--sed");
  EXPECT_EQ(nearest_word("--temperature", flags), "");
  EXPECT_EQ(nearest_word("--n", flags, 1), "--N");
  EXPECT_EQ(nearest_word("--M", flags, 1), "");
}

}  // namespace
}  // namespace granular
