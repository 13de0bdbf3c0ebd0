#include "granular/io/nearest_word.hpp"

#include <algorithm>
#include <cctype>

namespace granular {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const bool same =
          std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string nearest_word(const std::string& word, const std::vector<std::string>& candidates, std::size_t too_far) {
  std::string best;
  std::size_t best_distance = too_far;
  for (const std::string& candidate : candidates)
    if (const std::size_t d = edit_distance(word, candidate); d < best_distance) best_distance = d, best = candidate;
  return best;
}

}  // namespace granular
