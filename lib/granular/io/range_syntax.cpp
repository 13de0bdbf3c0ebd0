#include "granular/io/range_syntax.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

double parse_finite(std::string_view token, const std::string& option) {
  while (!token.empty() && token.front() == ' ') token.remove_prefix(1);
  while (!token.empty() && token.back() == ' ') token.remove_suffix(1);
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  double v = 0;
  auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (token.empty() || ec != std::errc() || end != token.data() + token.size() || !std::isfinite(v))
    throw InvalidInput(option, " '" + std::string(token.substr(0, 40)) + "': not a finite number");
  return v;
}

double round12(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.12g", v);
  double r = 0;
  std::from_chars(buffer, buffer + std::char_traits<char>::length(buffer), r);
  return r;
}

std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = text.find(sep, begin);
    parts.push_back(text.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin));
    if (end == std::string_view::npos) return parts;
    begin = end + 1;
  }
}

}  // namespace

std::vector<double> parse_number_list(const std::string& text, const std::string& option, double default_step,
                                      std::size_t max_count) {
  if (text.empty()) throw InvalidInput(option, ": empty value");
  std::vector<double> values;
  if (text.find(':') != std::string::npos) {
    const auto parts = split(text, ':');
    if (parts.size() > 3) throw InvalidInput(option, " '" + text + "': expected start:stop[:step]");
    const double start = parse_finite(parts[0], option);
    const double stop = parse_finite(parts[1], option);
    const double step = parts.size() == 3 ? parse_finite(parts[2], option) : default_step;
    if (!(step > 0)) throw InvalidInput(option, " '" + text + "': the step must be > 0");
    if (stop < start) throw InvalidInput(option, " '" + text + "': stop is below start");
    const double span = (stop - start) / step;
    if (!(span < static_cast<double>(max_count)))
      throw InvalidInput(option, " '" + text + "': more than " + std::to_string(max_count) + " values");
    const auto count = static_cast<std::size_t>(std::floor(span + 1e-9)) + 1;
    for (std::size_t i = 0; i < count; ++i) values.push_back(round12(start + static_cast<double>(i) * step));
    return values;
  }
  for (auto token : split(text, ',')) {
    values.push_back(parse_finite(token, option));
    if (values.size() > max_count) throw InvalidInput(option, ": more than " + std::to_string(max_count) + " values");
  }
  return values;
}

std::string format_number_list(const std::vector<double>& values) {
  std::string list;
  for (double v : values) {
    if (!list.empty()) list.push_back(',');
    list.append(format_number(v));
  }
  if (values.size() < 3) return list;
  const double step = round12(values[1] - values[0]);
  if (!(step > 0)) return list;
  std::string range = format_number(values.front());
  range.push_back(':');
  range.append(format_number(values.back()));
  range.push_back(':');
  range.append(format_number(step));
  try {
    if (range.size() < list.size() && parse_number_list(range, "range", 0, values.size()) == values) return range;
  } catch (const InvalidInput&) {  // not a range after all: the list says it
  }
  return list;
}

std::vector<long> parse_integer_list(const std::string& text, const std::string& option) {
  if (text.empty()) throw InvalidInput(option, ": empty value");
  std::vector<long> values;
  for (auto token : split(text, ',')) {
    long v = 0;
    auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (token.empty() || ec != std::errc() || end != token.data() + token.size())
      throw InvalidInput(option, " '" + std::string(token.substr(0, 40)) + "': not an integer");
    values.push_back(v);
  }
  return values;
}

Interval parse_interval(const std::string& text, const std::string& option) {
  const auto parts = split(text, ':');
  if (parts.size() != 2) throw InvalidInput(option, " '" + text + "': expected start:stop");
  const Interval i{parse_finite(parts[0], option), parse_finite(parts[1], option)};
  if (!(i.start < i.stop)) throw InvalidInput(option, " '" + text + "': start must be below stop");
  return i;
}

std::optional<double> parse_finite_number(const std::string& text) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string integer_digits(const std::string& text, const std::string& option) {
  if (text.find_first_of("eE.") == std::string::npos) return text;
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    return text;
  }
  if (used != text.size() || !std::isfinite(v) || v != std::floor(v) || std::fabs(v) > 9.2e18)
    throw InvalidInput(option + " " + text + ": not an integer");
  return std::to_string(static_cast<long long>(v));
}

std::vector<std::string> parse_word_list(const std::string& text, const std::string& option) {
  std::vector<std::string> words;
  for (auto token : split(text, ',')) {
    if (token.empty()) throw InvalidInput(option, " '" + text + "': empty item in the list");
    words.emplace_back(token);
  }
  return words;
}

}  // namespace granular
