#pragma once
// The exceptions the library throws. Tools map them to exit codes:
// InvalidInput -> 2 (the user asked for something impossible), IoError -> 1,
// NumericalError -> 3 (a solver failed; never silently returns garbage).
#include <stdexcept>
#include <string>

namespace granular {

/// A parameter or input file is invalid; the message names it, its value and the rule.
struct InvalidInput : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// Reading or writing a file failed.
struct IoError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A numerical method did not converge or produced a non-finite result.
struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace granular
