// describe_rows / parse_rows (parameter_json.hpp): for every row of every table of the library,
// a case with that row changed from its default is described and parsed back to the same case
// (compared through its description, so a row added to a table is covered without a new test).
#include "granular/parameter_json.hpp"
#include "granular/case/kicked_case.hpp"
#include "granular/study/ipr_map.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "granular/case/chain_choices.hpp"
#include "granular/case/spreading_outputs.hpp"
#include "granular/case/transport_parameters.hpp"
#include "granular/crystal/crystal_case.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/linear/mode_selection_choices.hpp"
#include "granular/linear/spectrum_parameters.hpp"
#include "granular/orbits/breather_parameters.hpp"
#include "granular/study/butterfly.hpp"
#include "granular/study/correlation_study.hpp"
#include "granular/study/crystal_ipr_map.hpp"
#include "granular/study/dynamical_butterfly.hpp"
#include "granular/study/exponent_choices.hpp"

namespace granular {
namespace {

/// `c` with row `p`'s field moved off its value (a number by a part in 1024, or to 1 from 0, a flag flipped, a word
/// changed, an optional set or reset); false for a row without a field (a text form alone).
template <class Case>
bool change_row(Case& c, const Parameter<Case>& p) {
  return std::visit(
      [&]<class Field>(const Field& field) {
        if constexpr (std::is_same_v<Field, std::monostate>) {
          return false;
        } else {
          auto& value = field(c);
          using T = std::remove_cvref_t<decltype(value)>;
          if constexpr (std::is_same_v<T, bool>) value = !value;
          else if constexpr (std::is_same_v<T, std::string>) value += "x";
          else if constexpr (std::is_floating_point_v<T>)
            value = value == 0 || value != value ? 1 : value * (1 + 0x1p-10);  // stays in order
          else if constexpr (std::is_integral_v<T>) value += 1;
          else if constexpr (requires { value.has_value(); }) {
            if (value) value.reset();
            else value = typename T::value_type{3};
          } else {
            value.push_back(7);  // a list
          }
          return true;
        }
      },
      p.field);
}

template <class Case>
void expect_every_row_round_trips(const ParameterTable<Case>& table, const char* name) {
  const Case defaults{};
  const nlohmann::json plain = describe_rows(defaults, table);
  EXPECT_EQ(describe_rows(parse_rows(plain, table), table), plain) << name;
  std::size_t changed = 0;
  for (const Parameter<Case>& p : table) {
    ASSERT_TRUE(plain.contains(p.name) || !p.text || !p.described) << name << ": " << p.name << " is not described";
    Case c = defaults;
    if (!change_row(c, p)) continue;
    ++changed;
    const nlohmann::json j = describe_rows(c, table);
    EXPECT_NE(j.at(p.name), plain.at(p.name)) << name << ": " << p.name;
    EXPECT_EQ(describe_rows(parse_rows(j, table), table), j) << name << ": " << p.name;
  }
  EXPECT_GT(changed, 0U) << name;
}

TEST(ParameterJson, EveryRowOfEveryTableRoundTrips) {
  expect_every_row_round_trips(chain_parameters(), "chain");
  expect_every_row_round_trips(transport_parameters(), "transport");
  expect_every_row_round_trips(mode_kick_parameters(), "mode kick");
  expect_every_row_round_trips(dynamical_butterfly_parameters(), "butterfly");
  expect_every_row_round_trips(exponent_parameters(), "exponents");
  expect_every_row_round_trips(exponent_table_parameters(), "exponent table");
  expect_every_row_round_trips(kicked_case_parameters(), "kicked case");
  expect_every_row_round_trips(ipr_map_parameters(), "IPR map");
  expect_every_row_round_trips(spreading_output_parameters(), "spreading outputs");
  expect_every_row_round_trips(mode_selection_parameters(), "mode selection");
  expect_every_row_round_trips(spectrum_parameters(), "spectrum solver");
  expect_every_row_round_trips(butterfly_parameters(), "butterfly (linear)");
  expect_every_row_round_trips(correlation_parameters(), "correlations");
  expect_every_row_round_trips(long_run_parameters(), "long run");
  expect_every_row_round_trips(breather_parameters(), "breathers");
  expect_every_row_round_trips(crystal_parameters(), "crystal");
  expect_every_row_round_trips(crystal_ipr_map_parameters(), "crystal IPR map");
}

/// Every row with a range (Parameter::range): its default passes check_ranges, and a value past its
/// low end (the end itself when open) or a NaN is refused naming the row.
template <class Case>
std::size_t expect_ranges_enforced(const ParameterTable<Case>& table, const char* name) {
  std::size_t checked = 0;
  EXPECT_NO_THROW(check_ranges(Case{}, table)) << name;
  for (const Parameter<Case>& p : table) {
    if (!p.range) continue;
    const double below = p.range->low_open ? p.range->low : p.range->low - 1;
    for (const double bad : {below, std::numeric_limits<double>::quiet_NaN()}) {
      Case c{};
      const bool set = std::visit(
          [&]<class Field>(const Field& field) {
            if constexpr (std::is_same_v<Field, std::monostate>) {
              return false;
            } else {
              auto& value = field(c);
              using T = std::remove_cvref_t<decltype(value)>;
              if constexpr (std::is_floating_point_v<T>) value = bad;
              else if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
                if (bad != bad || bad < static_cast<double>(std::numeric_limits<T>::lowest())) return false;
                value = static_cast<T>(bad);
              } else if constexpr (requires { value.has_value(); }) {
                if constexpr (std::is_floating_point_v<typename T::value_type>) value = bad;
                else return false;
              } else return false;
              return true;
            }
          },
          p.field);
      if (!set) continue;
      ++checked;
      try {
        check_ranges(c, table);
        ADD_FAILURE() << name << ": " << p.name << " = " << bad << " accepted";
      } catch (const InvalidInput& e) {
        EXPECT_EQ(e.parameter(), p.name) << e.what();
      }
    }
  }
  return checked;
}

TEST(ParameterJson, EveryRowsRangeIsEnforcedNamingIt) {
  EXPECT_GE(expect_ranges_enforced(transport_parameters(), "transport"), 8U);  // 4 rows, each below and NaN
  expect_ranges_enforced(case_parameters(), "kicked case");
}

TEST(ParameterJson, AValueOfTheWrongKindIsRefusedNamingItsKey) {
  nlohmann::json j = describe_rows(ModeSelectionChoices{}, mode_selection_parameters());
  j["count"] = "many";
  try {
    parse_rows(j, mode_selection_parameters());
    FAIL() << "a word taken as a count";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "count");
  }
}

}  // namespace
}  // namespace granular
