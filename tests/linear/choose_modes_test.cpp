// The one rule of the front ends' mode selection (choose_modes): near with count, a window, or every
// mode; each refusal names its parameter in the library's vocabulary.
#include <optional>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "granular/linear/spectrum.hpp"

namespace granular {
namespace {

using ChooseModesWindow = std::optional<std::pair<double, double>>;

/// The parameter the refusal of these choices names ("" when they are accepted).
std::string choose_modes_refusal(std::optional<double> near, std::optional<long> count, ChooseModesWindow window) {
  try {
    choose_modes(near, count, window);
  } catch (const InvalidInput& e) {
    return e.parameter();
  }
  return "";
}

void choose_modes_expect_same(const ModeSelection& got, const ModeSelection& want) {
  EXPECT_EQ(got.kind, want.kind);
  EXPECT_EQ(got.near_khz, want.near_khz);
  EXPECT_EQ(got.count, want.count);
  EXPECT_EQ(got.lo_khz, want.lo_khz);
  EXPECT_EQ(got.hi_khz, want.hi_khz);
}

TEST(ChooseModes, ValidChoicesGiveTheSelectionsOfNearestWindowAndAllModes) {
  choose_modes_expect_same(choose_modes(15.0, 20L, std::nullopt), nearest(15.0, 20));
  choose_modes_expect_same(choose_modes(std::nullopt, std::nullopt, std::pair{10.0, 12.5}), window(10.0, 12.5));
  choose_modes_expect_same(choose_modes(std::nullopt, std::nullopt, std::nullopt), all_modes());
  // what validate leaves to the chain (count beyond N, the window's order) is not refused here
  choose_modes_expect_same(choose_modes(std::nullopt, std::nullopt, std::pair{9.0, 3.0}), window(9.0, 3.0));
  choose_modes_expect_same(choose_modes(1000.0, 1L << 40, std::nullopt), nearest(1000.0, 1L << 40));
}

TEST(ChooseModes, EachRefusalNamesItsParameter) {
  EXPECT_EQ(choose_modes_refusal(15.0, std::nullopt, std::nullopt), "near");
  EXPECT_EQ(choose_modes_refusal(std::nullopt, 3L, std::nullopt), "count");
  EXPECT_EQ(choose_modes_refusal(15.0, 0L, std::nullopt), "count");
  EXPECT_EQ(choose_modes_refusal(15.0, -2L, std::nullopt), "count");
  EXPECT_EQ(choose_modes_refusal(15.0, 3L, std::pair{1.0, 2.0}), "window");
  EXPECT_EQ(choose_modes_refusal(15.0, std::nullopt, std::pair{1.0, 2.0}), "window");
  EXPECT_EQ(choose_modes_refusal(std::nullopt, 3L, std::pair{1.0, 2.0}), "window");
}

TEST(ChooseModes, MessagesNameOtherParametersInBackticksAndNoFlag) {
  const auto message = [](std::optional<double> near, std::optional<long> count, ChooseModesWindow window) {
    try {
      choose_modes(near, count, window);
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message(15.0, std::nullopt, std::nullopt), "near needs `count` (how many modes)");
  EXPECT_EQ(message(std::nullopt, 3L, std::nullopt), "count needs `near` (the target frequency in kHz)");
  EXPECT_EQ(message(15.0, 0L, std::nullopt), "count 0: must be >= 1");
  EXPECT_EQ(message(15.0, 3L, std::pair{1.0, 2.0}), "window cannot be combined with `near`/`count`");
}

}  // namespace
}  // namespace granular
