#pragma once
// The words that name the values of an enum (or of any small set of choices), as one constexpr
// table per set, and the two functions every such set needs: to_string (name_of) and parse. Each
// public pair (parse_kick / to_string(Kick), …) is a one-liner over its table, which sits beside it.
//
//   constexpr auto kick_names = detail::enum_names<Kick>(
//       "ic", {{Kick::displacement, "displacement"}, {Kick::velocity, "velocity"}, {Kick::mode, "mode"}});
//   kick_names.parse("mode");  // Kick::mode; "modes" throws InvalidInput("ic", " 'modes': expected
//                              //   displacement, velocity or mode")
#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "granular/error.hpp"

namespace granular::detail {

template <class T>
struct EnumName {
  T value;
  std::string_view name;
  bool alias = false;  ///< accepted by parse, but neither written by name_of nor listed in messages
};

/// How an error message lists the accepted words: "a, b or c", or "one of a, b, c".
enum class Listing { or_last, one_of };

/// ASCII letters compared without case ("RDM1" == "rdm1").
constexpr bool equal_ignoring_case(std::string_view a, std::string_view b) {
  const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [&](char x, char y) { return lower(x) == lower(y); });
}

template <class T, std::size_t N>
struct EnumNames {
  std::string_view parameter;  ///< what InvalidInput names
  std::array<EnumName<T>, N> names;
  bool any_case = false;  ///< parse ignores the case of ASCII letters
  Listing listing = Listing::or_last;

  /// The first non-alias word of `value`; "?" for a value the table lacks.
  constexpr std::string_view name_of(T value) const {
    for (const auto& n : names)
      if (!n.alias && n.value == value) return n.name;
    return "?";
  }

  /// The value `text` names; throws InvalidInput naming `parameter` (or `as`, when given) and
  /// listing the accepted words.
  T parse(std::string_view text, std::string_view as = {}) const {
    for (const auto& n : names)
      if (any_case ? equal_ignoring_case(text, n.name) : text == n.name) return n.value;
    throw InvalidInput(std::string(as.empty() ? parameter : as), " '" + std::string(text) + "': expected " + accepted());
  }

  /// The non-alias words, in table order, as the error message lists them.
  std::string accepted() const {
    std::string list = listing == Listing::one_of ? "one of " : "";
    std::size_t count = 0, total = 0;
    for (const auto& n : names) total += n.alias ? 0 : 1;
    for (const auto& n : names) {
      if (n.alias) continue;
      if (count > 0) list += listing == Listing::or_last && count + 1 == total ? " or " : ", ";
      list += n.name;
      ++count;
    }
    return list;
  }
};

/// The table of `T`'s words: enum_names<Kick>("ic", {{Kick::displacement, "displacement"}, …}).
template <class T, std::size_t N>
constexpr EnumNames<T, N> enum_names(std::string_view parameter, const EnumName<T> (&names)[N], bool any_case = false,
                                     Listing listing = Listing::or_last) {
  return {parameter, std::to_array(names), any_case, listing};
}

}  // namespace granular::detail
