// libFuzzer target: the "start:stop[:step]" / "a,b,c" option syntax must throw InvalidInput or
// return finite values, never crash, hang or allocate without bound.
#include <cmath>
#include <cstdint>
#include <string>

#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    for (double v : granular::parse_number_list(text, "--x", 0.01, 100000))
      if (!std::isfinite(v)) __builtin_trap();
  } catch (const granular::InvalidInput&) {
  }
  try {
    granular::parse_integer_list(text, "--x");
  } catch (const granular::InvalidInput&) {
  }
  return 0;
}
