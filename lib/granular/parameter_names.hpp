#pragma once
// The library's messages name parameters in its own vocabulary (`max_energy_error`, error.hpp);
// a front end tells them in the words its user typed (its command-line option, its keyword).
#include <functional>
#include <string>

namespace granular {

/// The word every front end uses for a library parameter where it is not the parameter's own
/// (the physics' symbols: precompression → F0, n → N, r1 → R1, time_step → dt, duration → T,
/// near_khz → near); the parameter itself otherwise. A tool's option is "--" and the word, a
/// Python keyword the word.
std::string front_end_word(const std::string& parameter);

/// `message` with every parameter name in it (a word of lowercase letters, digits and
/// underscores that holds an underscore) replaced by `name_of(word)`, or kept where that is "".
std::string rename_parameters(const std::string& message, const std::function<std::string(const std::string&)>& name_of);

}  // namespace granular
