#pragma once
// Which code made the realizations of a result resumed from another version's checkpoint: the
// "resumed_checkpoint" entry of a run's JSON.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace granular {

/// For a run that accepted checkpoints made by another version: which code made them
/// (`checkpoints`, the first that exists), which resumes them, and every version whose
/// realizations the result holds ("versions", oldest first: those of earlier accepted resumes
/// too, the union over a study's cases, this code last); null when no checkpoint exists.
/// Call before the run, which rewrites the checkpoints under this code's name.
nlohmann::json resumed_checkpoint(const std::vector<std::string>& checkpoints);

}  // namespace granular
