// The command-line form of a mode selection (spectrum, ipr-map): --near with --count, or --window F1:F2.
#include <gtest/gtest.h>

#include "../../tools/common/spectrum_options.hpp"

namespace granular {
namespace {

tool::SelectionOptions options(std::optional<double> near, std::optional<long> count, std::optional<std::string> w) {
  return {near, count, w};
}

TEST(SelectionOptions, ParsesTheCommandLineForm) {
  EXPECT_EQ(tool::parse_selection(options(15.0, 20L, std::nullopt)).count, 20);
  const auto w = tool::parse_selection(options(std::nullopt, std::nullopt, std::string("10:12.5")));
  EXPECT_EQ(w.kind, ModeSelection::Kind::window);
  EXPECT_DOUBLE_EQ(w.lo_khz, 10.0);
  EXPECT_DOUBLE_EQ(w.hi_khz, 12.5);
  EXPECT_EQ(tool::parse_selection(options(std::nullopt, std::nullopt, std::nullopt)).kind, ModeSelection::Kind::all);
  EXPECT_THROW(tool::parse_selection(options(15.0, std::nullopt, std::nullopt)), InvalidInput);
  EXPECT_THROW(tool::parse_selection(options(std::nullopt, 3L, std::nullopt)), InvalidInput);
  EXPECT_THROW(tool::parse_selection(options(15.0, 3L, std::string("1:2"))), InvalidInput);
  for (const char* bad : {"12", "1:2:3", "a:2", "1:", ":2", "1:2x", "1:nan"})
    EXPECT_THROW(tool::parse_selection(options(std::nullopt, std::nullopt, std::string(bad))), InvalidInput) << bad;
}

}  // namespace
}  // namespace granular
