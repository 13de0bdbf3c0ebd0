#pragma once
// The `spreading` command that computes one realization of a kicked-chain case alone, printed
// when a realization of an ensemble fails. The case is written whole, as its description
// (describe(), study/transport_study.hpp), to a file beside the run's outputs, and `spreading
// --case FILE` reads it back (kicked_case.hpp): every field travels, whatever flags set it.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "granular/io/atomic_file.hpp"
#include "granular/io/shell_quote.hpp"
#include "granular/study/transport_study.hpp"

namespace granular::tool {

/// Writes case `c` run alone (one realization, no profile) to PREFIX.replay-<r>-<hash of the case>.json
/// (cases of one study differ in the hash) and returns the `spreading` command that computes its
/// realization `r`; `argv0` (how this tool was called) says where `spreading` is. When the file
/// cannot be written, a sentence saying why.
inline std::string replay_text(const TransportCase& c, std::uint64_t r, const std::string& prefix,
                               const std::string& argv0) {
  TransportCase alone = c;
  alone.realizations = 1, alone.profile_realizations = 0;
  const std::string described = describe(alone).dump(2) + "\n";
  char hash[9];
  std::snprintf(hash, sizeof hash, "%08llx",
                static_cast<unsigned long long>(std::hash<std::string>{}(described)&0xffffffffULL));
  const std::string file = prefix + ".replay-" + std::to_string(r) + "-" + hash + ".json";
  try {
    write_file_atomically(file, described);
  } catch (const std::exception& e) {
    return std::string("(the case could not be written: ") + e.what() + ")";
  }
  const auto slash = argv0.rfind('/');
  const std::string folder = slash == std::string::npos ? "" : argv0.substr(0, slash + 1);
  return shell_quote(folder + "spreading") + " --case " + shell_quote(file) + " --realization " + std::to_string(r) +
         " --output replay-" + std::to_string(r);
}

}  // namespace granular::tool
