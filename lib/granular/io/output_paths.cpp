#include "granular/io/output_paths.hpp"

#include <filesystem>

#include "granular/error.hpp"
#include "granular/io/atomic_file.hpp"

namespace granular {

std::string output_prefix(const std::string& output) {
  const std::string ext = ".csv";
  if (output.size() > ext.size() && output.compare(output.size() - ext.size(), ext.size(), ext) == 0)
    return output.substr(0, output.size() - ext.size());
  return output;
}

void check_outputs(const std::vector<std::string>& paths, const std::string& names) {
  std::vector<std::filesystem::path> seen;
  for (const std::string& p : paths) {
    if (p.empty()) continue;
    const auto normal = std::filesystem::absolute(p).lexically_normal();
    for (const auto& s : seen)
      if (s == normal) throw InvalidInput(names + ": two outputs would both be " + p);
    seen.push_back(normal);
  }
  for (const std::string& p : paths)
    if (!p.empty()) check_writable(p);
}

TableOutputs table_outputs(const std::string& prefix) {
  TableOutputs paths{prefix + ".csv", prefix + ".json"};
  check_writable(paths.csv);
  check_writable(paths.json);
  return paths;
}

}  // namespace granular
