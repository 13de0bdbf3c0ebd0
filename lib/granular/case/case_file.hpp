#pragma once
// A kicked-chain case in a file of its own: the description (describe(), transport_study.hpp) of
// a case run alone, written beside a run's outputs when one of its realizations fails, so that
// every field travels to the command that replays it; and read back from such a file, or from a
// run's JSON, which holds one under "parameters".
#include <cstdint>
#include <string>

#include "granular/case/transport_case.hpp"

namespace granular {

/// Writes case `c` run alone (one realization, no profile) to PREFIX.replay-<r>-<hash>.json, the
/// hash of its description telling apart the cases of one study, and returns that path. Throws
/// IoError when it cannot be written.
std::string write_replay_case(const TransportCase& c, std::uint64_t r, const std::string& prefix);

/// The case the JSON file at `path` describes: a description, or a run's JSON with one under
/// "parameters". Throws InvalidInput naming `case` (unreadable, not a JSON object, or a
/// description parse_case refuses, its message told after the path).
TransportCase read_case_file(const std::string& path);

}  // namespace granular
