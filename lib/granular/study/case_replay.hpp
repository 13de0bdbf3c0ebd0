#pragma once
// Replaying one realization of an ensemble alone. When a realization fails, the user is told the
// command that computes it alone, so that it meets exactly what the ensemble met. A front end
// spells the case in its own arguments; before the command is printed, the arguments are read
// back as the front end reads them, and compared with the case field by field (describe(), the
// case's JSON): a case the arguments cannot spell (a material or a setting no argument names)
// gets no command, only the fields that differ.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "granular/study/transport_study.hpp"

namespace granular {

/// How a front end writes realization r of a case as its arguments, and reads arguments back as
/// the case it would run (validated and settled, exactly as it would run it).
struct CaseSpelling {
  std::function<std::vector<std::string>(const TransportCase&, std::uint64_t realization)> spell;
  std::function<TransportCase(const std::vector<std::string>&)> read;
};

/// The fields of describe() on which `got` differs from `want`, comma-separated ("" when none).
std::string differing_fields(const TransportCase& want, const TransportCase& got);

/// The arguments that compute realization `r` of `c` alone (one realization, no profile), or none
/// when they do not read back as that case: then `why` (if given) says which fields differ, or
/// why the arguments could not be read.
std::optional<std::vector<std::string>> replay_arguments(const TransportCase& c, std::uint64_t r,
                                                         const CaseSpelling& spelling, std::string* why = nullptr);

}  // namespace granular
