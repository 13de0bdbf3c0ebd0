#include "granular/study/case_replay.hpp"

#include <exception>

#include <nlohmann/json.hpp>

namespace granular {

std::string differing_fields(const TransportCase& want, const TransportCase& got) {
  const nlohmann::json a = describe(want), b = describe(got);
  std::string differ;
  const auto add = [&](const std::string& key) {
    if (!differ.empty()) differ += ", ";
    differ += key;
  };
  for (const auto& [key, value] : a.items())
    if (!b.contains(key) || b.at(key) != value) add(key);
  for (const auto& [key, value] : b.items())
    if (!a.contains(key)) add(key);
  return differ;
}

std::optional<std::vector<std::string>> replay_arguments(const TransportCase& c, std::uint64_t r,
                                                         const CaseSpelling& spelling, std::string* why) {
  TransportCase alone = c;  // what a single run computes: one realization, no profile
  alone.realizations = 1;
  alone.profile_realizations = 0;
  std::vector<std::string> arguments = spelling.spell(c, r);
  std::string differ;
  try {
    differ = differing_fields(alone, spelling.read(arguments));
  } catch (const std::exception& e) {
    differ = std::string("the flags do not read back: ") + e.what();
  }
  if (differ.empty()) return arguments;
  if (why) *why = differ;
  return std::nullopt;
}

}  // namespace granular
