#include "granular/ensemble/resumed_checkpoint.hpp"

#include <algorithm>
#include <filesystem>

#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/error.hpp"

namespace granular {

nlohmann::json resumed_checkpoint(const std::vector<std::string>& checkpoints) {
  for (const std::string& c : checkpoints)
    if (const std::string made_by = CheckpointLog::code_of(c); !made_by.empty()) {
      std::vector<std::string> versions;
      for (const std::string& each : checkpoints)
        for (const std::string& code : CheckpointLog::codes_of(each))
          if (std::find(versions.begin(), versions.end(), code) == versions.end()) versions.push_back(code);
      if (std::find(versions.begin(), versions.end(), CheckpointLog::this_code()) == versions.end())
        versions.push_back(CheckpointLog::this_code());
      return {{"made_by", made_by}, {"resumed_by", CheckpointLog::this_code()}, {"versions", versions}};
    }
  return nullptr;
}

void settle_checkpoints(const RunOptions& o, const std::string& checkpoint) {
  validate(o);
  if (!o.resuming()) CheckpointLog::settle(checkpoint, o.fresh, true);
}

nlohmann::json resumed_code(const RunOptions& o, const std::vector<std::string>& checkpoints) {
  if (o.resume && !o.accept_other_version)
    for (const std::string& c : checkpoints)
      if (const std::string other = CheckpointLog::other_version(c); !other.empty())
        throw InvalidInput("resume", ": " + other + "; resume it with the code that made it, or accept the mix with " +
                                         "`resume_other_version`");
  if (!o.resuming()) return nullptr;
  std::vector<std::string> kept;  // the checkpoints the run continues (a study's cases: one each)
  for (const std::string& c : checkpoints)
    if (std::filesystem::exists(c)) kept.push_back(c);
  if (kept.empty()) return nullptr;  // nothing to resume: the run starts afresh
  nlohmann::json j = o.accept_other_version ? resumed_checkpoint(checkpoints) : nlohmann::json::object();
  if (j.is_null()) j = nlohmann::json::object();
  j["files"] = kept;  // that it was resumed, and from which checkpoint
  return j;
}

}  // namespace granular
