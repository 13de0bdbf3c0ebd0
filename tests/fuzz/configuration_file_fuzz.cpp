// libFuzzer target: bead-type and radius files. Either a valid chain description or InvalidInput.
#include <cmath>
#include <cstdint>
#include <string>

#include "granular/error.hpp"
#include "granular/model/configuration_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    for (auto t : granular::parse_configuration_text(text, "fuzz"))
      if (t != 1 && t != 2) __builtin_trap();
  } catch (const granular::InvalidInput&) {
  }
  try {
    for (double r : granular::parse_radii_text(text, "fuzz"))
      if (!(r > 0) || !std::isfinite(r)) __builtin_trap();
  } catch (const granular::InvalidInput&) {
  }
  return 0;
}
