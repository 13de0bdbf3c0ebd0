#pragma once
// Commands a user can paste back into a POSIX shell: what a run's JSON records as its command
// line, and the commands a tool prints to resume or replay a run.
#include <string>
#include <vector>

namespace granular {

/// `word` as one word of a POSIX shell command: unchanged when it holds only characters no
/// shell treats specially (letters, digits, `_@%+=:,./-`), else in single quotes (a `'` inside
/// becomes `'\''`). The empty word is `''`.
std::string shell_quote(const std::string& word);

/// The words joined by spaces, each through shell_quote: pasted into a shell, it runs `words`.
std::string shell_command(const std::vector<std::string>& words);

}  // namespace granular
