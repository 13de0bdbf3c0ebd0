#include "granular/model/configuration_file.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "granular/error.hpp"
#include "granular/model/bead_distribution.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

// `parameter`: what names the file (config, radii), so that a tool says which flag to mend.
std::string read_text(const std::string& path, const char* parameter) {
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  const auto unreadable = [&] {
    const std::string why = errno != 0 ? std::strerror(errno) : "unreadable";
    return InvalidInput(parameter, " '" + path + "': cannot read the file (" + why + ")");
  };
  if (!in) throw unreadable();
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw unreadable();
  return text.str();
}

/// Calls `take(token, line_number)` for every value line, with comments and blanks stripped.
template <class Take>
void for_each_value(const std::string& text, const std::string& source, Take take) {
  if (text.find('\0') != std::string::npos) throw InvalidInput(source + ": binary data, expected one value per line");
  std::size_t line_number = 0, begin = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    ++line_number;
    std::string_view line(text.data() + begin, end - begin);
    if (auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.front()))) line.remove_prefix(1);
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.remove_suffix(1);
    if (!line.empty()) take(line, line_number);
    begin = end + 1;
  }
}

[[noreturn]] void bad_line(const std::string& source, std::size_t line, std::string_view token, const char* rule) {
  throw InvalidInput(source + ":" + std::to_string(line) + ": '" + std::string(token.substr(0, 40)) + "' " + rule);
}

}  // namespace

Configuration parse_configuration_text(const std::string& text, const std::string& source) {
  Configuration types;
  for_each_value(text, source, [&](std::string_view token, std::size_t line) {
    if (token != "1" && token != "2") bad_line(source, line, token, "is not a bead type (1 or 2)");
    types.push_back(token == "1" ? 1 : 2);
  });
  if (types.size() < 2) throw InvalidInput(source + ": needs at least 2 beads, found " + std::to_string(types.size()));
  return types;
}

std::string implausible_radius_warning(const std::string& where, double r) {
  return where + ": radius " + format_number(r) + " m is outside the plausible range " +
         format_number(plausible_radius_min) + " - " + format_number(plausible_radius_max) +
         " m of the contact law (millimetres typed as metres?)";
}

std::vector<double> parse_radii_text(const std::string& text, const std::string& source,
                                     std::vector<std::string>* warnings) {
  std::vector<double> radii;
  for_each_value(text, source, [&](std::string_view token, std::size_t line) {
    double r = 0;
    auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), r);
    if (ec != std::errc() || end != token.data() + token.size()) bad_line(source, line, token, "is not a number");
    if (!std::isfinite(r) || r <= 0) bad_line(source, line, token, "is not a radius (finite, > 0, metres)");
    if (warnings && !plausible_radius(r))
      warnings->push_back(implausible_radius_warning(source + ":" + std::to_string(line), r));
    radii.push_back(r);
  });
  if (radii.size() < 2) throw InvalidInput(source + ": needs at least 2 beads, found " + std::to_string(radii.size()));
  return radii;
}

std::vector<double> parse_displacements_text(const std::string& text, const std::string& source) {
  std::vector<double> u;
  for_each_value(text, source, [&](std::string_view token, std::size_t line) {
    double x = 0;
    auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), x);
    if (ec != std::errc() || end != token.data() + token.size()) bad_line(source, line, token, "is not a number");
    if (!std::isfinite(x)) bad_line(source, line, token, "is not a finite displacement (metres)");
    u.push_back(x);
  });
  if (u.empty()) throw InvalidInput(source + ": no displacements");
  return u;
}

std::vector<double> read_displacements_file(const std::string& path, const char* parameter) {
  return parse_displacements_text(read_text(path, parameter), path);
}

Configuration read_configuration_file(const std::string& path) {
  return parse_configuration_text(read_text(path, "config"), path);
}

std::vector<double> read_radii_file(const std::string& path, std::vector<std::string>* warnings) {
  return parse_radii_text(read_text(path, "radii"), path, warnings);
}

}  // namespace granular
