#pragma once
// The exceptions the library throws, all of them granular::Error. Front ends map them: the
// command-line tools to exit codes (InvalidInput -> 2: the user asked for something impossible;
// IoError -> 1; NumericalError -> 3: a solver failed, never silently returns garbage), the Python
// module to ValueError, OSError and granular.NumericalError.
#include <stdexcept>
#include <string>

namespace granular {

/// The base of every exception the library throws: `catch (const granular::Error&)` takes them
/// all. Each also derives from the standard exception it always has (InvalidInput from
/// std::invalid_argument, the others from std::runtime_error), so `catch (const std::exception&)`
/// takes them too; what() is that standard exception's message.
struct Error {
  virtual ~Error() = default;
  virtual const char* what() const noexcept = 0;
};

/// A parameter or input file is invalid. The message names the parameter in the library's
/// vocabulary (`time_step`, `N`, `q`), its value and the rule; front ends translate the name into
/// their own (`--dt`, the keyword `dt=`), which is why it is also kept apart. Other parameters the
/// rule names are written in backticks ("only with `mle`"), which front ends tell in their words
/// too (parameter_table.hpp: tell_parameters).
struct InvalidInput : std::invalid_argument, Error {
  /// `parameter` is the name, `problem` the rest, starting with its own separator (" 0: must be
  /// > 0", ": no values"); what() is their concatenation.
  InvalidInput(const std::string& parameter, const std::string& problem)
      : std::invalid_argument(parameter + problem), parameter_(parameter), problem_(problem) {}
  /// A message that names no single parameter (a file's content, a combination).
  explicit InvalidInput(const std::string& message) : std::invalid_argument(message), problem_(message) {}

  const char* what() const noexcept override { return std::invalid_argument::what(); }
  const std::string& parameter() const { return parameter_; }  ///< empty when none
  const std::string& problem() const { return problem_; }

 private:
  std::string parameter_, problem_;
};

/// Reading or writing a file failed.
struct IoError : std::runtime_error, Error {
  using std::runtime_error::runtime_error;
  const char* what() const noexcept override { return std::runtime_error::what(); }
};

/// A numerical method did not converge or produced a non-finite result.
struct NumericalError : std::runtime_error, Error {
  using std::runtime_error::runtime_error;
  const char* what() const noexcept override { return std::runtime_error::what(); }
};

/// The caller asked a long run to stop (RunOptions::cancelled returned true). Thrown once the
/// realizations in flight have finished and been checkpointed, so the run can be resumed.
struct Cancelled : std::runtime_error, Error {
  Cancelled() : std::runtime_error("cancelled") {}
  const char* what() const noexcept override { return std::runtime_error::what(); }
};

}  // namespace granular
