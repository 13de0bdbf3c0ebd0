// Commands pasted back into a shell run the very words they were made from.
#include "granular/io/shell_quote.hpp"

#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace granular {
namespace {

TEST(ShellQuote, LeavesPlainWordsAndQuotesTheRest) {
  const std::vector<std::pair<std::string, std::string>> quoted{
      {"--F0", "--F0"},    {"a/b.csv", "a/b.csv"},       {"4.76e-3:0.5,3e-3:0.5", "4.76e-3:0.5,3e-3:0.5"},
      {"", "''"},          {"two words", "'two words'"}, {"it's", "'it'\\''s'"},
      {"$HOME", "'$HOME'"}};
  for (const auto& [word, expected] : quoted) EXPECT_EQ(shell_quote(word), expected) << word;
}

TEST(ShellQuote, ACommandJoinsQuotedWords) {
  EXPECT_EQ(shell_command({}), "");
  EXPECT_EQ(shell_command({"spreading", "--output", "my run"}), "spreading --output 'my run'");
}

}  // namespace
}  // namespace granular
