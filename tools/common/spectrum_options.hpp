#pragma once
// The options that choose modes and a solver (spectrum, ipr-map): --near/--count or --window, --method.
#include <cmath>
#include <optional>
#include <string>

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

/// Exactly one of (--near with --count) or --window "F1:F2"; every mode when none is given.
inline ModeSelection parse_selection(const SelectionOptions& o) {
  if (!o.given()) return all_modes();
  if (o.window) {
    if (o.near || o.count) throw InvalidInput("--window", " cannot be combined with --near/--count");
    const std::string& w = *o.window;
    const auto colon = w.find(':');
    auto khz = [&](const std::string& text) {
      if (const auto v = parse_finite_number(text)) return *v;
      throw InvalidInput("--window", " '" + w + "': expected F1:F2, two frequencies in kHz");
    };
    if (colon == std::string::npos || w.find(':', colon + 1) != std::string::npos)
      throw InvalidInput("--window", " '" + w + "': expected F1:F2, two frequencies in kHz");
    return window(khz(w.substr(0, colon)), khz(w.substr(colon + 1)));
  }
  if (o.near && !o.count) throw InvalidInput("--near", " needs --count K (how many modes)");
  if (o.count && !o.near) throw InvalidInput("--count", " needs --near KHZ (the target frequency)");
  return nearest(*o.near, *o.count);
}

}  // namespace granular::tool
