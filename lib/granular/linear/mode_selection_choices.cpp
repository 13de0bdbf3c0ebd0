#include "granular/linear/mode_selection_choices.hpp"

#include <string>

#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

// The command line's text form of `window`: two frequencies F1:F2 [kHz]; an empty text is none.
void read_window(ModeSelectionChoices& o, const std::string& text) {
  if (text.empty()) return o.window.reset();
  const auto colon = text.find(':');  // a second colon leaves no number after the first
  const auto lo = parse_finite_number(text.substr(0, colon)), hi = parse_finite_number(text.substr(colon + 1));
  if (colon == std::string::npos || !lo || !hi)
    throw InvalidInput("window", " '" + text + "': expected F1:F2, two frequencies in kHz");
  o.window = {*lo, *hi};
}
std::string write_window(const ModeSelectionChoices& o) {
  return o.window ? format_number(o.window->first) + ":" + format_number(o.window->second) : "";
}

}  // namespace

const ParameterTable<ModeSelectionChoices>& mode_selection_parameters() {
  using O = ModeSelectionChoices;
  static const ParameterTable<O> table{
      {"near", &O::near, "the `count` modes nearest this frequency [kHz] (with `count`)", false},
      {"count", &O::count, "how many modes nearest `near` (1 <= K <= N)", false},
      {"window", {}, {read_window, write_window}, "every mode in F1:F2 [kHz], both ends included", false}};
  return table;
}

ModeSelection choose_modes(const ModeSelectionChoices& o) { return choose_modes(o.near, o.count, o.window); }

}  // namespace granular
