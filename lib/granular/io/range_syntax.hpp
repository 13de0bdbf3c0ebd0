#pragma once
// The command-line list syntax: "start:stop[:step]" (stop included) or "a,b,c".
#include <optional>
#include <string>
#include <vector>

namespace granular {

/// Parses a list or range of finite numbers. Range values are rounded to 12 significant
/// digits so that 0.1:1:0.1 gives 0.3, not 0.30000000000000004. `option` names the
/// option in error messages (InvalidInput). A range without step uses `default_step`
/// (an error when that is 0). At most `max_count` values.
std::vector<double> parse_number_list(const std::string& text, const std::string& option, double default_step = 0,
                                      std::size_t max_count = 1000000);

/// The text parse_number_list reads back as `values`: "start:stop:step" when they are that range
/// and it is the shorter, else a comma list (format_number's shortest forms); "" for none.
std::string format_number_list(const std::vector<double>& values);

/// Parses a comma list of positive integers (e.g. particle numbers).
std::vector<long> parse_integer_list(const std::string& text, const std::string& option);

/// `text` read whole as one finite number (std::stod's syntax), or none: empty, trailing
/// characters, out of range, inf or nan.
std::optional<double> parse_finite_number(const std::string& text);

/// A whole number as an integer parser reads it: "1e7" and "2.5e3" become "10000000" and "2500";
/// text with no exponent or point, or that is no number at all, comes back unchanged (the integer
/// parser reports it). Throws InvalidInput "<option> <text>: not an integer" for a number that is
/// not whole, not finite or beyond ±9.2e18.
std::string integer_digits(const std::string& text, const std::string& option);

/// An interval "start:stop" with finite start < stop (e.g. a fit window, 4e-3:1e-2).
struct Interval {
  double start, stop;
};
Interval parse_interval(const std::string& text, const std::string& option);

/// Splits a comma list of words ("h,A,RDM1"); empty items are an error naming the option.
std::vector<std::string> parse_word_list(const std::string& text, const std::string& option);

}  // namespace granular
