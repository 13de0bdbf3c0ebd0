#pragma once
// Before and after a run resumed from checkpoints: an interrupted run's checkpoints continued or
// discarded (never overwritten), and which code made the realizations of a result resumed from
// another version's checkpoint, the "resumed_checkpoint" entry of a run's JSON.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "granular/ensemble/run_options.hpp"

namespace granular {

/// For a run that accepted checkpoints made by another version: which code made them
/// (`checkpoints`, the first that exists), which resumes them, and every version whose
/// realizations the result holds ("versions", oldest first: those of earlier accepted resumes
/// too, the union over a study's cases, this code last); null when no checkpoint exists.
/// Call before the run, which rewrites the checkpoints under this code's name.
nlohmann::json resumed_checkpoint(const std::vector<std::string>& checkpoints);

/// Before a run that logs its finished realizations to `checkpoint` (and, a study of several cases,
/// to checkpoint.<case>): unless it resumes, the logs an interrupted run left there are refused
/// (InvalidInput naming `checkpoint`: finished work is never lost to a run not told to discard it),
/// or with `fresh` removed. Validates the choices.
void settle_checkpoints(const RunOptions& o, const std::string& checkpoint);

/// For the JSON of a run that resumes (RunOptions::resuming()) from checkpoints that
/// exist: "files", those checkpoints, and accepting other versions which code made their
/// realizations (resumed_checkpoint() above); null for a run that resumes nothing. A plain `resume` of
/// a checkpoint another version made is refused (InvalidInput naming `resume`). Call before the
/// run, which rewrites the checkpoints under this code's name.
nlohmann::json resumed_code(const RunOptions& o, const std::vector<std::string>& checkpoints);

}  // namespace granular
