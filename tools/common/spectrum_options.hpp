#pragma once
// The options that choose modes and a solver (spectrum, ipr-map): --near/--count or --window, --method.
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/linear/spectrum.hpp"

namespace granular::tool {

struct SelectionOptions {
  std::optional<double> near;
  std::optional<long> count;
  std::optional<std::string> window;
  bool given() const { return near || count || window; }
};

inline void add_selection_options(CLI::App& app, SelectionOptions& o, const std::string& what) {
  app.add_option("--near", o.near, what + "the --count modes nearest this frequency [kHz] (with --count)");
  app.add_option("--count", o.count, what + "how many modes nearest --near (1 <= K <= N)");
  app.add_option("--window", o.window, what + "every mode in F1:F2 [kHz], both ends included");
}

/// Exactly one of (--near with --count) or --window "F1:F2"; every mode when none is given: the
/// library's rule (choose_modes) once --window's text is read as two frequencies.
inline ModeSelection parse_selection(const SelectionOptions& o) {
  std::optional<std::pair<double, double>> khz;
  if (o.window) {
    const std::string& w = *o.window;
    const auto colon = w.find(':');  // a second colon leaves no number after the first
    const auto lo = parse_finite_number(w.substr(0, colon)), hi = parse_finite_number(w.substr(colon + 1));
    if (colon == std::string::npos || !lo || !hi)
      throw InvalidInput("window", " '" + w + "': expected F1:F2, two frequencies in kHz");
    khz = {*lo, *hi};
  }
  return choose_modes(o.near, o.count, khz);
}

}  // namespace granular::tool
