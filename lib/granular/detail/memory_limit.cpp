#include "granular/detail/memory_limit.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace granular::detail {
namespace {

// A limit file's number of bytes; nullopt for "max" (v2's none), empty or anything not a number.
std::optional<double> parse_bytes(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\n");
  if (first == std::string::npos) return std::nullopt;
  const auto last = text.find_last_not_of(" \t\n");
  const std::string word = text.substr(first, last - first + 1);
  if (word.empty() || word.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  return std::stod(word);
}

// The cgroup and each ancestor up to the hierarchy's root: "/a/b" -> "/a/b", "/a", "".
std::vector<std::string> with_ancestors(std::string path) {
  std::vector<std::string> out;
  while (!path.empty() && path.back() == '/') path.pop_back();
  while (true) {
    out.push_back(path);
    const auto slash = path.rfind('/');
    if (path.empty() || slash == std::string::npos) break;
    path.erase(slash);
  }
  return out;
}

}  // namespace

MemoryLimit memory_limit(const MemorySources& s) {
  MemoryLimit out;
  const auto consider = [&](double bytes, const char* source) {
    if (bytes > 0 && std::isfinite(bytes) && (out.bytes == 0 || bytes < out.bytes))
      out.bytes = bytes, out.source = source;
  };
  consider(s.physical, "physical memory");
  consider(s.address_space, "RLIMIT_AS (ulimit -v)");
  if (!s.read_file) return out;
  const auto cgroups = s.read_file("/proc/self/cgroup");
  if (!cgroups) return out;
  // Lines "hierarchy-ID:controller-list:path": v2's is "0::path"; v1's memory controller has
  // "memory" in its comma-separated list.
  std::istringstream lines(*cgroups);
  for (std::string line; std::getline(lines, line);) {
    const auto colon = line.find(':'), second = colon == std::string::npos ? colon : line.find(':', colon + 1);
    if (second == std::string::npos) continue;
    const std::string id = line.substr(0, colon), controllers = line.substr(colon + 1, second - colon - 1),
                      path = line.substr(second + 1);
    if (id == "0" && controllers.empty()) {
      for (const char* mount : {"/sys/fs/cgroup", "/sys/fs/cgroup/unified"})
        for (const std::string& group : with_ancestors(path))
          if (const auto text = s.read_file(mount + group + "/memory.max"))
            if (const auto bytes = parse_bytes(*text)) consider(*bytes, "cgroup v2 memory.max");
    } else if (("," + controllers + ",").find(",memory,") != std::string::npos) {
      for (const std::string& group : with_ancestors(path))
        if (const auto text = s.read_file("/sys/fs/cgroup/memory" + group + "/memory.limit_in_bytes"))
          if (const auto bytes = parse_bytes(*text)) consider(*bytes, "cgroup v1 memory.limit_in_bytes");
    }
  }
  return out;
}

MemoryLimit memory_limit() {
  MemorySources s;
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) s.physical = static_cast<double>(pages) * static_cast<double>(page);
  rlimit as{};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
    s.address_space = static_cast<double>(as.rlim_cur);
  s.read_file = [](const std::string& path) -> std::optional<std::string> {
    std::ifstream in(path);
    if (!in) return std::nullopt;
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  return memory_limit(s);
}

}  // namespace granular::detail
