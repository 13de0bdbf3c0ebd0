#pragma once
// Numbers as text: the shortest string that reads back to the same double.
#include <string>

namespace granular {

/// Shortest round-trip decimal form ("0.1", "1e-07", "nan", "inf").
std::string format_number(double value);

}  // namespace granular
