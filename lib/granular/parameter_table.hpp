#pragma once
// A struct of choices describes its parameters once, in one table: each parameter's name, the
// field it sets and what it means, with units. Every front end is made of that table — a tool
// its options and their --help lines, Python its attributes — so a parameter added to the table
// reaches all of them, in each front end's words (parameter_names.hpp).
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "granular/parameter_names.hpp"

namespace granular {

/// How a command line writes a parameter that is not one number or word (a fit window
/// "start:stop", a velocity or 'match', a comma list): `read` sets the choices from such a text
/// (throwing InvalidInput that names the parameter), `write` says the choices' value in it.
template <class Choices>
struct TextForm {
  void (*read)(Choices&, const std::string&) = nullptr;
  std::string (*write)(const Choices&) = nullptr;
};

template <class Choices>
struct Parameter {
  /// The member the parameter sets; none (monostate) when front ends read it in forms of their
  /// own (a fit window: `text` on the command line, a pair in Python) and set fields of it.
  using Field =
      std::variant<std::monostate, double Choices::*, long long Choices::*, long Choices::*, unsigned long Choices::*,
                   std::string Choices::*, bool Choices::*, std::optional<double> Choices::*,
                   std::optional<long> Choices::*, std::vector<long> Choices::*>;

  Parameter(std::string name, Field field, std::string help, bool shows_default = true)
      : name(std::move(name)), field(field), help(std::move(help)), shows_default(shows_default) {}
  Parameter(std::string name, Field field, TextForm<Choices> text, std::string help, bool shows_default = true)
      : Parameter(std::move(name), field, std::move(help), shows_default) {
    this->text = text;
  }

  std::string name;  ///< the library's name, the one its messages use (`time_step`)
  Field field;
  /// Meaning and units. A parameter written in backticks (`time_step`) is told in the front
  /// end's word for it (--dt, dt).
  std::string help;
  bool shows_default = true;  ///< whether the default says something (not a "none" sentinel)
  /// A command line's text form, if the parameter has one; front ends that take values rather
  /// than text (Python) set `field`.
  std::optional<TextForm<Choices>> text{};
};

template <class Choices>
using ParameterTable = std::vector<Parameter<Choices>>;

/// The word front ends use for `p` (a tool's option is "--" and it, '_' as '-'; a Python keyword is it).
template <class Choices>
std::string word_of(const Parameter<Choices>& p) {
  return front_end_word(p.name);
}

/// The row of `table` named `name`. Throws std::out_of_range when there is none (a programming error).
template <class Choices>
const Parameter<Choices>& parameter(const ParameterTable<Choices>& table, std::string_view name) {
  for (const Parameter<Choices>& p : table)
    if (p.name == name) return p;
  throw std::out_of_range("no parameter " + std::string(name));
}

/// `help` with every parameter in backticks replaced by `told(parameter)`.
std::string tell_parameters(const std::string& help, const std::function<std::string(const std::string&)>& told);

}  // namespace granular
