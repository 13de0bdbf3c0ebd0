#pragma once
// Numbers as text: the shortest string that reads back to the same double. Every module's
// error messages and every output file use it, so it sits beside error.hpp, below the modules.
#include <charconv>
#include <cmath>
#include <string>

namespace granular {

/// Shortest round-trip decimal form ("0.1", "1e-07", "nan", "inf").
inline std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, end);
}

}  // namespace granular
