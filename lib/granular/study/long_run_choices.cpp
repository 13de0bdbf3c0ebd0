#include "granular/study/long_run_choices.hpp"

#include <filesystem>

#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/error.hpp"
#include "granular/study/resumed_checkpoint.hpp"

namespace granular {

const ParameterTable<LongRunChoices>& long_run_parameters() {
  using O = LongRunChoices;
  static const ParameterTable<O> table{
      {"threads", &O::threads, "threads per process (0 = all cores); results do not depend on it"},
      {"resume", &O::resume, "continue an interrupted run (same parameters) from its checkpoint"},
      {"resume_other_version", &O::resume_other_version,
       "as `resume`, and accept a checkpoint made by another granular version or commit (both are named in the "
       "metadata)"},
      {"fresh", &O::fresh, "discard the checkpoint of an interrupted run and start again"},
      {"skip_failed", &O::skip_failed,
       "leave a realization that fails numerically out of the means (counted in the metadata) instead of stopping "
       "at it"}};
  return table;
}

void validate(const LongRunChoices& o) {
  if (o.threads < 0 || o.threads > 4096)
    throw InvalidInput("threads", " " + std::to_string(o.threads) + ": 0 (every core) to 4096");
  if (o.resuming() && o.fresh)
    throw InvalidInput("fresh", ": not with `resume` (continue, or start again: one of them)");
}

RunOptions run_options(const LongRunChoices& o, const std::string& checkpoint) {
  validate(o);
  if (o.resuming() && checkpoint.empty())
    throw InvalidInput("resume", ": needs `checkpoint` (the file or prefix of the interrupted run)");
  return {.threads = static_cast<int>(o.threads),
          .checkpoint = checkpoint,
          .resume = o.resuming(),
          .skip_failed = o.skip_failed,
          .accept_other_version = o.resume_other_version,
          .fresh = o.fresh};
}

void settle_checkpoints(const LongRunChoices& o, const std::string& checkpoint) {
  validate(o);
  if (!o.resuming()) CheckpointLog::settle(checkpoint, o.fresh, true);
}

nlohmann::json resumed_code(const LongRunChoices& o, const std::vector<std::string>& checkpoints) {
  if (o.resume && !o.resume_other_version)
    for (const std::string& c : checkpoints)
      if (const std::string other = CheckpointLog::other_version(c); !other.empty())
        throw InvalidInput("resume", ": " + other + "; resume it with the code that made it, or accept the mix with " +
                                         "`resume_other_version`");
  if (!o.resuming()) return nullptr;
  std::vector<std::string> kept;  // the checkpoints the run continues (a study's cases: one each)
  for (const std::string& c : checkpoints)
    if (std::filesystem::exists(c)) kept.push_back(c);
  if (kept.empty()) return nullptr;  // nothing to resume: the run starts afresh
  nlohmann::json j = o.resume_other_version ? resumed_checkpoint(checkpoints) : nlohmann::json::object();
  if (j.is_null()) j = nlohmann::json::object();
  j["files"] = kept;  // that it was resumed, and from which checkpoint
  return j;
}

}  // namespace granular
