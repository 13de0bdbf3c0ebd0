// detail::memory_limit: the least of RAM, the cgroup's limit (v2 and v1, the process's group and
// its ancestors) and RLIMIT_AS, read from made-up values and files.
#include <cstdio>
#include <map>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "granular/detail/memory_limit.hpp"

namespace granular::detail {
namespace {

constexpr double gib = 1024.0 * 1024.0 * 1024.0;

MemorySources sources_with(double physical, double address_space, std::map<std::string, std::string> files) {
  MemorySources s;
  s.physical = physical;
  s.address_space = address_space;
  s.read_file = [files = std::move(files)](const std::string& path) -> std::optional<std::string> {
    const auto it = files.find(path);
    if (it == files.end()) return std::nullopt;
    return it->second;
  };
  return s;
}

TEST(MemoryLimit, PhysicalMemoryWhenNothingElseLimits) {
  const MemoryLimit m = memory_limit(sources_with(24 * gib, 0, {}));
  EXPECT_EQ(m.bytes, 24 * gib);
  EXPECT_EQ(m.source, "physical memory");
  EXPECT_EQ(memory_limit(MemorySources{}).bytes, 0);  // nothing known
  // v2 "max" and v1's "unlimited" 2^63 - 4096 leave the RAM.
  const MemoryLimit unlimited =
      memory_limit(sources_with(24 * gib, 0,
                                {{"/proc/self/cgroup", "4:memory:/job\n0::/user.slice/session\n"},
                                 {"/sys/fs/cgroup/user.slice/session/memory.max", "max\n"},
                                 {"/sys/fs/cgroup/memory/job/memory.limit_in_bytes", "9223372036854771712\n"}}));
  EXPECT_EQ(unlimited.bytes, 24 * gib);
}

TEST(MemoryLimit, CgroupV2MaxOfTheGroupOrAnAncestor) {
  const std::string cgroup = "0::/system.slice/job-42.scope\n";
  const MemoryLimit own =
      memory_limit(sources_with(24 * gib, 0,
                                {{"/proc/self/cgroup", cgroup},
                                 {"/sys/fs/cgroup/system.slice/job-42.scope/memory.max", "2147483648\n"}}));
  EXPECT_EQ(own.bytes, 2 * gib);
  EXPECT_EQ(own.source, "cgroup v2 memory.max");
  // A parent's limit binds its children; the tightest counts.
  const MemoryLimit parent = memory_limit(sources_with(24 * gib, 0,
                                                       {{"/proc/self/cgroup", cgroup},
                                                        {"/sys/fs/cgroup/system.slice/job-42.scope/memory.max", "max"},
                                                        {"/sys/fs/cgroup/system.slice/memory.max", "1073741824"}}));
  EXPECT_EQ(parent.bytes, 1 * gib);
  // In a cgroup namespace the group is "/" and its limit is at the mount's top.
  const MemoryLimit namespaced = memory_limit(
      sources_with(24 * gib, 0, {{"/proc/self/cgroup", "0::/\n"}, {"/sys/fs/cgroup/memory.max", "536870912\n"}}));
  EXPECT_EQ(namespaced.bytes, 0.5 * gib);
  // The hybrid layout mounts v2 at /sys/fs/cgroup/unified.
  const MemoryLimit hybrid = memory_limit(
      sources_with(24 * gib, 0,
                   {{"/proc/self/cgroup", "0::/a\n"}, {"/sys/fs/cgroup/unified/a/memory.max", "3221225472"}}));
  EXPECT_EQ(hybrid.bytes, 3 * gib);
}

TEST(MemoryLimit, CgroupV1LimitInBytes) {
  const MemoryLimit v1 = memory_limit(
      sources_with(24 * gib, 0,
                   {{"/proc/self/cgroup", "9:name=systemd:/\n4:memory:/process_api/6e9a\n1:cpu,cpuacct:/other\n"},
                    {"/sys/fs/cgroup/memory/process_api/6e9a/memory.limit_in_bytes", "4294967296\n"},
                    {"/sys/fs/cgroup/memory/other/memory.limit_in_bytes", "1"}}));  // not the memory controller's
  EXPECT_EQ(v1.bytes, 4 * gib);
  EXPECT_EQ(v1.source, "cgroup v1 memory.limit_in_bytes");
  // "memory" within a comma-separated list of controllers; "memory_x" is another controller.
  const MemoryLimit listed = memory_limit(sources_with(24 * gib, 0,
                                                       {{"/proc/self/cgroup", "3:cpu,memory:/g\n2:memory_x:/h\n"},
                                                        {"/sys/fs/cgroup/memory/g/memory.limit_in_bytes", "8589934592"},
                                                        {"/sys/fs/cgroup/memory/h/memory.limit_in_bytes", "1"}}));
  EXPECT_EQ(listed.bytes, 8 * gib);
}

TEST(MemoryLimit, AddressSpaceLimitAndBadFiles) {
  const MemoryLimit as = memory_limit(sources_with(24 * gib, 3 * gib, {}));
  EXPECT_EQ(as.bytes, 3 * gib);
  EXPECT_EQ(as.source, "RLIMIT_AS (ulimit -v)");
  // The least of all three.
  const MemoryLimit all =
      memory_limit(sources_with(24 * gib, 3 * gib,
                                {{"/proc/self/cgroup", "0::/j\n"}, {"/sys/fs/cgroup/j/memory.max", "1073741824"}}));
  EXPECT_EQ(all.bytes, 1 * gib);
  // Unreadable, empty, negative or malformed contents are no limit.
  const MemoryLimit bad = memory_limit(sources_with(24 * gib, 0,
                                                    {{"/proc/self/cgroup", "0::/j\ngarbage\n4:memory:/k\n"},
                                                     {"/sys/fs/cgroup/j/memory.max", ""},
                                                     {"/sys/fs/cgroup/memory.max", "-5"},
                                                     {"/sys/fs/cgroup/memory/k/memory.limit_in_bytes", "12 GB"},
                                                     {"/sys/fs/cgroup/memory/memory.limit_in_bytes", "0"}}));
  EXPECT_EQ(bad.bytes, 24 * gib);
  EXPECT_EQ(bad.source, "physical memory");
}

// This machine's: positive, and at most its RAM.
TEST(MemoryLimit, ThisProcessHasOne) {
  const MemoryLimit m = memory_limit();
  EXPECT_GT(m.bytes, 0);
  EXPECT_FALSE(m.source.empty());
  std::printf("this process may use %.3g bytes (%s)\n", m.bytes, m.source.c_str());
}

}  // namespace
}  // namespace granular::detail
