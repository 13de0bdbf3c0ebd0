#pragma once
// The library's messages name parameters in its own vocabulary (`max_energy_error`, error.hpp);
// a front end tells them in the words its user typed (its command-line option, its keyword).
#include <functional>
#include <string>

namespace granular {

/// `message` with every parameter name in it (a word of lowercase letters, digits and
/// underscores that holds an underscore) replaced by `name_of(word)`, or kept where that is "".
std::string rename_parameters(const std::string& message, const std::function<std::string(const std::string&)>& name_of);

}  // namespace granular
