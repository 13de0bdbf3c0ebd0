#include "granular/parameter_names.hpp"

#include <cctype>
#include <map>

namespace granular {

std::string front_end_word(const std::string& parameter) {
  static const std::map<std::string, std::string> words{{"precompression", "F0"},
                                                        {"n", "N"},
                                                        {"r1", "R1"},
                                                        {"time_step", "dt"},
                                                        {"duration", "T"},
                                                        {"near_khz", "near"},
                                                        {"floquet_method", "floquet"},
                                                        {"floquet_multipliers", "multipliers"}};
  const auto it = words.find(parameter);
  return it == words.end() ? parameter : it->second;
}

std::string rename_parameters(const std::string& message, const std::function<std::string(const std::string&)>& name_of) {
  std::string out, word;
  const auto flush = [&] {
    const std::string name = word.find('_') != std::string::npos ? name_of(word) : "";
    out += name.empty() ? word : name;
    word.clear();
  };
  for (char c : message) {
    if (std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_') {
      word += c;
      continue;
    }
    flush();
    out += c;
  }
  flush();
  return out;
}

}  // namespace granular
