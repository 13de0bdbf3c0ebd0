#pragma once
// Flags declared once: a row names the flag, the option field it sets and its help. The same rows
// register the options (add_flags) and spell a case's values back as flags (spell_flags, for the
// replay command), so the two cannot drift apart: what a tool reads is what it writes.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>

#include "granular/number_format.hpp"
#include "granular/study/transport_study.hpp"

namespace granular::tool {

template <class Options>
struct Flag {
  std::string name;
  std::variant<double Options::*, long long Options::*, long Options::*, std::string Options::*,
               std::optional<double> Options::*>
      field;
  std::string help;
  bool shows_default = true;                        ///< --help shows the default value
  bool (*spelled)(const TransportCase&) = nullptr;  ///< when a replay writes it (null: always)
};

/// Registers every row of `flags` on `app`, bound to its field of `o`.
template <class Options>
void add_flags(CLI::App& app, Options& o, const std::vector<Flag<Options>>& flags) {
  for (const Flag<Options>& f : flags)
    std::visit(
        [&](auto field) {
          CLI::Option* option = app.add_option(f.name, o.*field, f.help);
          if (f.shows_default) option->capture_default_str();
        },
        f.field);
}

/// The value as a flag takes it: numbers in shortest round-trip form.
inline std::string flag_value(double x) { return format_number(x); }
inline std::string flag_value(long long x) { return std::to_string(x); }
inline std::string flag_value(long x) { return std::to_string(x); }
inline std::string flag_value(const std::string& x) { return x; }
inline std::string flag_value(const std::optional<double>& x) { return x ? format_number(*x) : ""; }

/// Appends to `words` the rows of `flags` that case `c` spells, with their values in `o` (the
/// options that give `c`).
template <class Options>
void spell_flags(const std::vector<Flag<Options>>& flags, const Options& o, const TransportCase& c,
                 std::vector<std::string>& words) {
  for (const Flag<Options>& f : flags)
    if (!f.spelled || f.spelled(c))
      words.insert(words.end(), {f.name, std::visit([&](auto field) { return flag_value(o.*field); }, f.field)});
}

}  // namespace granular::tool
