// The text form of a mode selection as the command line types it (spectrum, ipr-map): --near with
// --count, or --window F1:F2 read by the library's text form (mode_selection_choices.hpp), then
// the library's rule (choose_modes).
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "granular/error.hpp"
#include "granular/linear/mode_selection_choices.hpp"

namespace granular {
namespace {

/// The selection of the options as typed, --window as its text.
ModeSelection typed(std::optional<double> near, std::optional<long> count, std::optional<std::string> window) {
  ModeSelectionChoices choices{.near = near, .count = count};
  if (window) parameter(mode_selection_parameters(), "window").text->read(choices, *window);
  return choose_modes(choices);
}

TEST(ModeSelectionText, ReadsTheCommandLineForm) {
  EXPECT_EQ(typed(15.0, 20L, std::nullopt).count, 20);
  const auto w = typed(std::nullopt, std::nullopt, std::string("10:12.5"));
  EXPECT_EQ(w.kind, ModeSelection::Kind::window);
  EXPECT_DOUBLE_EQ(w.lo_khz, 10.0);
  EXPECT_DOUBLE_EQ(w.hi_khz, 12.5);
  EXPECT_EQ(typed(std::nullopt, std::nullopt, std::nullopt).kind, ModeSelection::Kind::all);
  EXPECT_THROW(typed(15.0, std::nullopt, std::nullopt), InvalidInput);
  EXPECT_THROW(typed(std::nullopt, 3L, std::nullopt), InvalidInput);
  EXPECT_THROW(typed(15.0, 3L, std::string("1:2")), InvalidInput);
  for (const char* bad : {"12", "1:2:3", "a:2", "1:", ":2", "1:2x", "1:nan"})
    EXPECT_THROW(typed(std::nullopt, std::nullopt, std::string(bad)), InvalidInput) << bad;
}

}  // namespace
}  // namespace granular
