#pragma once
// The memory this process may use, for the guards that refuse a run which would not fit before
// it starts (spectrum's every-mode solve with eigenvectors, spreading's energy map): the least of
// the host's physical memory, the memory limit of the process's cgroup and RLIMIT_AS. In a
// container, a batch job's cgroup or under `ulimit -v`, the host's RAM is not what the process
// can have: a guard reading it alone lets through a run that the kernel then kills (cgroup) or
// that fails with bad_alloc hours in (RLIMIT_AS).
#include <functional>
#include <optional>
#include <string>

namespace granular::detail {

struct MemoryLimit {
  double bytes = 0;    ///< the least of the known limits [bytes]; 0 when none is known
  std::string source;  ///< which one: "physical memory", "cgroup v2 memory.max", "cgroup v1
                       ///< memory.limit_in_bytes" or "RLIMIT_AS (ulimit -v)"
};

/// What the limit is computed from, so that the tests can feed made-up values and files.
struct MemorySources {
  double physical = 0;       ///< the host's physical memory [bytes] (sysconf); 0: unknown
  double address_space = 0;  ///< RLIMIT_AS's soft limit [bytes]; 0 or infinite: none
  /// A file's contents, nullopt when it cannot be read: /proc/self/cgroup, then memory.max (v2,
  /// under /sys/fs/cgroup or the hybrid /sys/fs/cgroup/unified) and memory.limit_in_bytes (v1,
  /// under /sys/fs/cgroup/memory) of the process's cgroup and of each ancestor (a parent's limit
  /// binds its children too). "max" and unparsable contents are no limit.
  std::function<std::optional<std::string>(const std::string& path)> read_file;
};

/// The least of sources' limits (0 bytes, source empty, when none is known).
MemoryLimit memory_limit(const MemorySources& sources);

/// This process's: sysconf(_SC_PHYS_PAGES) × page size, getrlimit(RLIMIT_AS) and the files.
MemoryLimit memory_limit();

}  // namespace granular::detail
