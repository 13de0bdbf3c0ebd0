#pragma once
// How a front end asks a long, checkpointed run to go — threads, continuing or discarding an
// interrupted run's checkpoint, leaving failed realizations out — as opposed to what it computes.
// Errors name the choice in the library's words (`threads`, `resume`); each front end tells it in
// its own.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "granular/ensemble/run_options.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

struct LongRunChoices {
  long long threads = 0;              ///< worker threads per process, 0 = every core (at most 4096)
  bool resume = false;                ///< continue an interrupted run from its checkpoint
  bool resume_other_version = false;  ///< as resume, accepting a checkpoint another version or commit made
  bool fresh = false;                 ///< discard an interrupted run's checkpoint and start again
  bool skip_failed = false;           ///< leave a realization that fails numerically out of the means
  bool resuming() const { return resume || resume_other_version; }
};

/// Each choice's meaning (parameter_table.hpp).
const ParameterTable<LongRunChoices>& long_run_parameters();

/// Throws InvalidInput naming `threads` (below 0 or above 4096) or `fresh` (with `resume`).
void validate(const LongRunChoices& o);

/// The library's RunOptions of the choices, logging finished realizations to `checkpoint` (a file
/// or a study's prefix; "" = none). Validates them; resuming needs a checkpoint (InvalidInput naming `resume`).
RunOptions run_options(const LongRunChoices& o, const std::string& checkpoint);

/// Before a run that logs its finished realizations to `checkpoint` (and, a study of several cases,
/// to checkpoint.<case>): unless it resumes, the logs an interrupted run left there are refused
/// (InvalidInput naming `checkpoint`: finished work is never lost to a run not told to discard it),
/// or with `fresh` removed. Validates the choices.
void settle_checkpoints(const LongRunChoices& o, const std::string& checkpoint);

/// For the JSON of a run that resumes (`resume` or `resume_other_version`) from checkpoints that
/// exist: "files", those checkpoints, and with resume_other_version which code made their
/// realizations (resumed_checkpoint.hpp); null for a run that resumes nothing. A plain `resume` of
/// a checkpoint another version made is refused (InvalidInput naming `resume`). Call before the
/// run, which rewrites the checkpoints under this code's name.
nlohmann::json resumed_code(const LongRunChoices& o, const std::vector<std::string>& checkpoints);

}  // namespace granular
