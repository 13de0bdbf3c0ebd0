#pragma once
// A case's JSON made from its table (parameter_table.hpp): describe_rows writes one key per row,
// the row's name, with its value (a text form as its text, an unset optional or a NaN number as null), and
// parse_rows reads them back into a case. Two loops over the same rows, so a row added to a
// table is described, replayed and round-trip tested without another line.
#include <limits>
#include <string>
#include <type_traits>
#include <variant>

#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

/// {row name: value} for every row of `table` that has a field or a text form (not a shorthand).
template <class Case>
nlohmann::json describe_rows(const Case& c, const ParameterTable<Case>& table) {
  nlohmann::json j = nlohmann::json::object();
  for (const Parameter<Case>& p : table)
    if (p.described)
      std::visit(
          [&]<class Field>(const Field& field) {
            if constexpr (std::is_same_v<Field, std::monostate>) {
              if (p.text && p.text->write) j[p.name] = p.text->write(c);  // a word or a text form
            } else {
              const auto& value = field(const_cast<Case&>(c));
              using T = std::remove_cvref_t<decltype(value)>;
              if constexpr (requires { value.has_value(); })
                j[p.name] = value ? nlohmann::json(*value) : nlohmann::json(nullptr);
              else if constexpr (std::is_floating_point_v<T>)  // NaN, a number's "none", is null in JSON
                j[p.name] = value == value ? nlohmann::json(value) : nlohmann::json(nullptr);
              else j[p.name] = value;
            }
          },
          p.field);
  return j;
}

/// `c` with every row of `table` whose name is a key of `j` set from it (the inverse of
/// describe_rows; rows without a key keep their value in `c`). Throws InvalidInput naming the key
/// when its value has the wrong type or its text form refuses it.
template <class Case>
Case parse_rows(const nlohmann::json& j, const ParameterTable<Case>& table, Case c = Case{}) {
  for (const Parameter<Case>& p : table) {
    if (!p.described || !j.contains(p.name)) continue;
    const nlohmann::json& v = j.at(p.name);
    try {
      if (std::holds_alternative<std::monostate>(p.field)) {
        if (p.text && p.text->read) p.text->read(c, v.get<std::string>());
        continue;
      }
      std::visit(
          [&]<class Field>(const Field& field) {
            if constexpr (!std::is_same_v<Field, std::monostate>) {
              auto& value = field(c);
              using T = std::remove_cvref_t<decltype(value)>;
              if constexpr (requires { value.has_value(); }) {
                if (v.is_null()) value.reset();
                else value = v.get<typename T::value_type>();
              } else if constexpr (std::is_floating_point_v<T>) {
                value = v.is_null() ? std::numeric_limits<T>::quiet_NaN() : v.get<T>();
              } else {
                value = v.get<T>();
              }
            }
          },
          p.field);
    } catch (const nlohmann::json::exception&) {
      throw InvalidInput(p.name, ": " + v.dump() + " is not a value of this parameter");
    }
  }
  return c;
}

}  // namespace granular
