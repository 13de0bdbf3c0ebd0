#include "granular/io/range_syntax.hpp"

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

TEST(RangeSyntax, RangesIncludeStopAndRoundCleanly) {
  const auto xi = parse_number_list("0.1:1", "--xi", 0.01);
  ASSERT_EQ(xi.size(), 91u);
  EXPECT_EQ(xi.front(), 0.1);
  EXPECT_EQ(xi[20], 0.3);  // not 0.30000000000000004
  EXPECT_EQ(xi.back(), 1.0);
  EXPECT_EQ(parse_number_list("1:2:0.5", "--x"), (std::vector<double>{1, 1.5, 2}));
  EXPECT_EQ(parse_number_list("0.2,0.5,0.8", "--q"), (std::vector<double>{0.2, 0.5, 0.8}));
  EXPECT_EQ(parse_number_list("4e-3:1e-2:2e-3", "--fit"), (std::vector<double>{4e-3, 6e-3, 8e-3, 1e-2}));
}

TEST(RangeSyntax, AListIsWrittenAsTheTextThatReadsItBack) {
  const std::vector<double> grid = parse_number_list("0.1:1", "xi", 0.01);
  EXPECT_EQ(format_number_list(grid), "0.1:1:0.01") << "a range, when shorter than its list";
  EXPECT_EQ(parse_number_list(format_number_list(grid), "xi"), grid);
  EXPECT_EQ(format_number_list({0.2, 0.5, 0.8}), "0.2,0.5,0.8") << "as short as its range: a list";
  EXPECT_EQ(format_number_list({10, 0.5, 0.1, 0.01, 0}), "10,0.5,0.1,0.01,0");
  EXPECT_EQ(format_number_list({1, 2, 4, 5, 6, 7}), "1,2,4,5,6,7") << "not one step";
  EXPECT_EQ(format_number_list({}), "");
  for (const auto& values : {std::vector<double>{0.3, 0.1, 0.2}, std::vector<double>{1e-3, 2e-3, 3e-3, 4e-3},
                             parse_number_list("0.005:0.995:0.005", "r")})
    EXPECT_EQ(parse_number_list(format_number_list(values), "x"), values) << format_number_list(values);
}

TEST(RangeSyntax, RejectsMalformedInputNamingTheOption) {
  for (const char* bad :
       {"", "a", "1:", ":1", "1:2:0", "1:2:-1", "2:1", "1:2:3:4", "nan", "1,inf", "1,,2", "0.1:1:1e-9"}) {
    try {
      parse_number_list(bad, "--xi", 0.01, 1000);
      FAIL() << "accepted '" << bad << "'";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("--xi"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(parse_number_list("0:1", "--xi"), InvalidInput);  // no default step
}

TEST(RangeSyntax, AFiniteNumberIsReadWhole) {
  EXPECT_EQ(parse_finite_number("15.5"), 15.5);
  EXPECT_EQ(parse_finite_number("-1e-3"), -1e-3);
  EXPECT_FALSE(parse_finite_number(""));
  EXPECT_FALSE(parse_finite_number("15kHz"));
  EXPECT_FALSE(parse_finite_number("inf"));
  EXPECT_FALSE(parse_finite_number("nan"));
  EXPECT_FALSE(parse_finite_number("1e999"));
}

TEST(RangeSyntax, WholeNumbersInScientificNotationBecomeDigits) {
  EXPECT_EQ(integer_digits("2501", "--N"), "2501");
  EXPECT_EQ(integer_digits("1e7", "--N"), "10000000");
  EXPECT_EQ(integer_digits("2.5e3", "--N"), "2500");
  EXPECT_EQ(integer_digits("abc", "--N"), "abc");  // left to the integer parser
  EXPECT_EQ(integer_digits("-1", "--N"), "-1");
  try {
    integer_digits("2.5", "--N");
    FAIL() << "2.5 was read as an integer";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "--N 2.5: not an integer");
  }
  EXPECT_THROW(integer_digits("1e19", "--seed"), InvalidInput);
  EXPECT_THROW(integer_digits("1e3x", "--seed"), InvalidInput);
}

TEST(NumberFormat, ShortestRoundTrip) {
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(1e-7), "1e-07");
  const double x = 0.30000000000000004;
  EXPECT_EQ(std::stod(format_number(x)), x);
  EXPECT_EQ(format_number(std::numeric_limits<double>::quiet_NaN()), "nan");
}

TEST(IntegerList, ParsesAndRejects) {
  EXPECT_EQ(parse_integer_list("601,631,661", "--forces-at"), (std::vector<long>{601, 631, 661}));
  EXPECT_THROW(parse_integer_list("1,a", "--forces-at"), InvalidInput);
  EXPECT_THROW(parse_integer_list("1.5", "--forces-at"), InvalidInput);
}

}  // namespace
}  // namespace granular
