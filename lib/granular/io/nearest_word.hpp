#pragma once
// "Did you mean …?": the known word nearest a mistyped one, by edit distance.
#include <cstddef>
#include <string>
#include <vector>

namespace granular {

/// Levenshtein distance of `a` and `b` (insertions, deletions, substitutions; letters compared
/// case-insensitively).
std::size_t edit_distance(const std::string& a, const std::string& b);

/// The first of `candidates` nearest `word`, if it is fewer than `too_far` edits away; else "".
std::string nearest_word(const std::string& word, const std::vector<std::string>& candidates, std::size_t too_far = 3);

}  // namespace granular
