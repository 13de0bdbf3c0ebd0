#pragma once
// A struct of choices describes its parameters once, in one table: each parameter's name, the
// field it sets and what it means, with units. Every front end is made of that table — a tool
// its options and their --help lines, Python its attributes — so a parameter added to the table
// reaches all of them, in each front end's words (parameter_names.hpp).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
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
  std::function<void(Choices&, const std::string&)> read{};
  std::function<std::string(const Choices&)> write{};
};

/// What a parameter takes effect with: another choice of its table on (a word given, a flag set, a
/// number not 0, an optional set) and, if `values` are listed, one of them (case-insensitive; the
/// first is the one messages name). A parameter given without it is refused, not ignored.
struct Needs {
  std::string choice;
  std::vector<std::string> values{};
};

/// Where a parameter's value lives in `Choices`: a member (`&TransportCase::alpha`) or a path into
/// a nested member (path(&TransportCase::dynamics, &SpreadingRunConfig::integration,
/// &IntegrationConfig::duration)), so that a table can describe the typed case itself.
template <class Choices, class T>
using Ref = std::function<T&(Choices&)>;

/// The reference to the member reached from a `Root` by `members` in turn (c.*m1.*m2…).
template <class Root, class... Members>
auto path(Members... members) {
  return [members...](Root & c) -> auto& { return (c.*....*members); };
}

/// The values a number may take: finite, and within [low, high] (an end `open`: excluded).
struct Range {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool low_open = false;
  bool high_open = false;
};

template <class Choices>
struct Parameter {
  /// The value the parameter sets; none (monostate) when front ends read it in forms of their
  /// own (a fit window: `text` on the command line, a pair in Python) and set fields of it.
  using Field = std::variant<std::monostate, Ref<Choices, double>, Ref<Choices, int>, Ref<Choices, long long>,
                             Ref<Choices, long>, Ref<Choices, unsigned long>, Ref<Choices, std::string>,
                             Ref<Choices, bool>, Ref<Choices, std::optional<double>>, Ref<Choices, std::optional<long>>,
                             Ref<Choices, std::vector<long>>, Ref<Choices, std::vector<double>>>;

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
  /// The choice the parameter takes effect with (`angle`: `quasi` cylinders); none: always.
  std::optional<Needs> needs{};
  /// Choices that leave this parameter without effect when they are on (`q` with `quasi`: the
  /// chain's beads come from it), or set to one of the words after the name ("disorder h
  /// homogeneous": `q` with one bead type). Given with one, the parameter is refused, not ignored.
  std::vector<std::string> overridden_by{};

  /// Whether the text form is also Python's attribute (a word standing for a typed value: an
  /// enum, `integrator`); other text forms are the command line's only.
  bool python_text = false;

  /// The values the number may take (an optional: when set), which check_ranges enforces; none: any.
  std::optional<Range> range{};

  /// Whether the JSON holds this row (describe_rows): not a command line's shorthand for other
  /// rows (`fit` start:stop for `fit_begin` and `fit_end`), which they describe.
  bool described = true;

  /// Words front ends took for this parameter before it was renamed (`mode_khz`: the tools'
  /// --mode-khz, Python's mode_khz=), still taken for one minor version with a deprecation note.
  std::vector<std::string> former_words{};

  /// This row, also taken under its former front-end `word` (deprecated).
  Parameter formerly(std::string word) && {
    former_words.push_back(std::move(word));
    return std::move(*this);
  }

  /// This row, its number finite and > 0.
  Parameter positive() && {
    range = Range{.low = 0, .low_open = true};
    return std::move(*this);
  }

  /// This row, its number finite and >= `low`.
  Parameter at_least(double low) && {
    range = Range{.low = low};
    return std::move(*this);
  }

  /// This row, a shorthand for other rows that the JSON holds instead (`described`).
  Parameter shorthand() && {
    described = false;
    return std::move(*this);
  }

  /// This row, its text form also Python's attribute (a word).
  Parameter as_word() && {
    python_text = true;
    return std::move(*this);
  }

  /// This row, taking effect only with `choice` (set to one of `values`, if any).
  Parameter needing(std::string choice, std::vector<std::string> values = {}) && {
    needs = Needs{std::move(choice), std::move(values)};
    return std::move(*this);
  }

  /// This row, without effect (and so refused when given) while any of `choices` is on.
  Parameter overridden(std::vector<std::string> choices) && {
    overridden_by = std::move(choices);
    return std::move(*this);
  }
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

namespace detail {
inline std::string lowercase(const std::string& text) {
  std::string out;
  std::transform(text.begin(), text.end(), std::back_inserter(out),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}
template <class T>
bool same_value(const T& a, const T& b) {
  if constexpr (std::is_floating_point_v<T>) return a == b || (a != a && b != b);  // NaN defaults
  else return a == b;
}
template <class T>
bool is_on(const T& v) {
  if constexpr (std::is_same_v<T, std::string>) return !v.empty();
  else if constexpr (requires { v.has_value(); }) return v.has_value();
  else if constexpr (requires { v.empty(); }) return !v.empty();
  else return v != T{};
}
/// The refusal of a parameter given without what it `needs`: `state` is the needed choice's
/// word when it is on (a word not among the values); when it is off, "" for a choice not given (a
/// word, an optional) and "off" for a flag or number (0).
[[noreturn]] void refuse_unmet(const std::string& name, const Needs& needs, const std::string& state);
/// The refusal of a parameter given with a choice that overrides it (Parameter::overridden_by).
[[noreturn]] void refuse_overridden(const std::string& name, const std::string& choice);

/// Whether the choice of row `p` is on in `o` (a word given, a flag set, a number not 0, an
/// optional set), and its word, lowercase, when it is one; `flag`: a flag or number (off, not absent).
template <class Choices>
bool choice_on(const Choices& o, const Parameter<Choices>& p, std::string& word, bool& flag) {
  return std::visit(
      [&]<class Field>(const Field& field) {
        if constexpr (std::is_same_v<Field, std::monostate>) {
          if (p.text) word = lowercase(p.text->write(o));  // a word form (`integrator`)
          return !word.empty();
        } else {
          const auto& value = field(const_cast<Choices&>(o));
          using T = std::remove_cvref_t<decltype(value)>;
          if constexpr (std::is_same_v<T, std::string>) word = lowercase(value);
          flag = std::is_arithmetic_v<T>;
          return is_on(value);
        }
      },
      p.field);
}
}  // namespace detail

/// Whether `o` sets `p` to other than its default in `defaults` (a text form compared as written).
template <class Choices>
bool given(const Choices& o, const Parameter<Choices>& p, const Choices& defaults) {
  if (p.text && p.text->write) return p.text->write(o) != p.text->write(defaults);
  return std::visit(
      [&]<class Field>(const Field& field) {
        if constexpr (std::is_same_v<Field, std::monostate>) return false;
        else return !detail::same_value(field(const_cast<Choices&>(o)), field(const_cast<Choices&>(defaults)));
      },
      p.field);
}

/// Refuses every parameter of `table` that `o` gives (not its default in `defaults`) without the
/// choice it needs (Parameter::needs), or with a choice that overrides it (Parameter::overridden_by):
/// throws InvalidInput naming it and that choice, so an option never is silently ignored ("`angle`:
/// takes effect only with `quasi` cylinders, not `quasi` s1"; "`q`: takes no effect with `quasi`").
template <class Choices>
void refuse_unmet_needs(const Choices& o, const ParameterTable<Choices>& table, const Choices& defaults = Choices{}) {
  for (const Parameter<Choices>& p : table) {
    if ((!p.needs && p.overridden_by.empty()) || !given(o, p, defaults)) continue;
    for (const std::string& entry : p.overridden_by) {
      const std::string choice = entry.substr(0, entry.find(' '));
      std::string word;
      bool flag = false;
      if (!detail::choice_on(o, parameter(table, choice), word, flag)) continue;
      const std::string values =
          entry.size() > choice.size() ? detail::lowercase(entry.substr(choice.size())) + " " : "";
      if (values.empty()) detail::refuse_overridden(p.name, choice);
      else if (values.find(" " + word + " ") != std::string::npos)
        detail::refuse_overridden(p.name, choice + " " + word);
    }
    if (!p.needs) continue;
    std::string word;   // the needed choice's word, lowercase
    bool flag = false;  // a flag or number: off rather than not given
    const bool on = detail::choice_on(o, parameter(table, p.needs->choice), word, flag);
    const auto& values = p.needs->values;
    if (on && (values.empty() || std::find(values.begin(), values.end(), word) != values.end())) continue;
    detail::refuse_unmet(p.name, *p.needs, on ? word : flag ? "off" : "");
  }
}

namespace detail {
/// The refusal of `value` outside `range`, naming `name`: "`fit_step` -1: must be finite and > 0".
[[noreturn]] void refuse_out_of_range(const std::string& name, double value, const Range& range);
}  // namespace detail

/// Refuses a number of `o` outside its row's range (Parameter::range; an unset optional passes):
/// throws InvalidInput naming the row. A row's checks live in its row, so a new row is validated
/// without another line.
template <class Choices>
void check_ranges(const Choices& o, const ParameterTable<Choices>& table) {
  for (const Parameter<Choices>& p : table) {
    if (!p.range) continue;
    std::visit(
        [&]<class Field>(const Field& field) {
          if constexpr (!std::is_same_v<Field, std::monostate>) {
            const auto& value = field(const_cast<Choices&>(o));
            using T = std::remove_cvref_t<decltype(value)>;
            const auto check = [&](double x) {
              const Range& r = *p.range;
              const bool below = r.low_open ? !(x > r.low) : !(x >= r.low);
              const bool above = r.high_open ? !(x < r.high) : !(x <= r.high);
              if (below || above || !std::isfinite(x)) detail::refuse_out_of_range(p.name, x, r);
            };
            if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) check(static_cast<double>(value));
            else if constexpr (requires { value.has_value(); }) {
              if constexpr (std::is_arithmetic_v<typename T::value_type>)
                if (value) check(static_cast<double>(*value));
            }
          }
        },
        p.field);
  }
}

/// The rows of `table` (over a part `Inner` of a case) as rows of the case `Outer` that holds it in
/// `member`, for the rows named in `names` (all when empty), in the table's order: a job whose case
/// nests another's (a crystal IPR map's crystal) takes that case's rows, help and checks as they
/// are, written once. Needs and overrides keep their names (rows of the same nested table); those
/// naming a row left out are dropped.
template <class Outer, class Inner>
ParameterTable<Outer> nested_rows(const ParameterTable<Inner>& table, Inner Outer::*member,
                                  const std::vector<std::string>& names = {}) {
  ParameterTable<Outer> out;
  for (const Parameter<Inner>& p : table) {
    if (!names.empty() && std::find(names.begin(), names.end(), p.name) == names.end()) continue;
    typename Parameter<Outer>::Field field = std::visit(
        [&]<class F>(const F& inner) -> typename Parameter<Outer>::Field {
          if constexpr (std::is_same_v<F, std::monostate>) {
            return std::monostate{};
          } else {
            using T = std::remove_cvref_t<decltype(inner(std::declval<Inner&>()))>;
            return Ref<Outer, T>([inner, member](Outer& o) -> T& { return inner(o.*member); });
          }
        },
        p.field);
    Parameter<Outer> row(p.name, field, p.help, p.shows_default);
    if (p.text)
      row.text =
          TextForm<Outer>{p.text->read
                              ? [read = p.text->read, member](Outer& o, const std::string& t) { read(o.*member, t); }
                              : std::function<void(Outer&, const std::string&)>{},
                          p.text->write ? [write = p.text->write, member](const Outer& o) { return write(o.*member); }
                                        : std::function<std::string(const Outer&)>{}};
    // A need or an override of a row left out has nothing to look at: the outer case sets that
    // choice its own way (a crystal IPR map's `widths` for the crystal's `width`).
    const auto kept = [&](const std::string& entry) {
      const std::string choice = entry.substr(0, entry.find(' '));
      return names.empty() || std::find(names.begin(), names.end(), choice) != names.end();
    };
    if (p.needs && kept(p.needs->choice)) row.needs = Needs{p.needs->choice, p.needs->values};
    for (const std::string& entry : p.overridden_by)
      if (kept(entry)) row.overridden_by.push_back(entry);
    row.python_text = p.python_text;
    row.described = p.described;
    row.range = p.range;
    row.former_words = p.former_words;
    out.push_back(std::move(row));
  }
  return out;
}

/// The note a front end gives when a parameter is set under its former word: "--mode-khz is
/// deprecated: use --near (the old spelling goes in the next minor version)", each word as the
/// front end tells it.
std::string deprecation_note(const std::string& former, const std::string& now);

/// `help` with every parameter in backticks replaced by `told(parameter)`.
std::string tell_parameters(const std::string& help, const std::function<std::string(const std::string&)>& told);

}  // namespace granular
