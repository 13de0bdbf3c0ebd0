#include "granular/case/case_file.hpp"

#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/text_hash.hpp"

namespace granular {

std::string write_replay_case(const TransportCase& c, std::uint64_t r, const std::string& prefix) {
  TransportCase alone = c;
  alone.realizations = 1, alone.profile_realizations = 0;
  const std::string described = describe(alone).dump(2) + "\n";
  char hash[9];
  std::snprintf(hash, sizeof hash, "%08llx", static_cast<unsigned long long>(text_hash(described) & 0xffffffffULL));
  const std::string file = prefix + ".replay-" + std::to_string(r) + "-" + hash + ".json";
  write_file_atomically(file, described);
  return file;
}

TransportCase read_case_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InvalidInput("case", " '" + path + "': cannot be read");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object()) throw InvalidInput("case", " '" + path + "': not a JSON object");
  try {
    return parse_case(j.contains("parameters") ? j.at("parameters") : j);
  } catch (const InvalidInput& e) {
    throw InvalidInput("case", " '" + path + "': " + e.what());
  }
}

}  // namespace granular
