#include "granular/ensemble/run_options.hpp"

#include "granular/error.hpp"

namespace granular {

const ParameterTable<RunOptions>& long_run_parameters() {
  using O = RunOptions;
  static const ParameterTable<O> table{
      {"threads", &O::threads, "threads per process (0 = all cores); results do not depend on it"},
      {"resume", &O::resume, "continue an interrupted run (same parameters) from its checkpoint"},
      {"resume_other_version", &O::accept_other_version,
       "as `resume`, and accept a checkpoint made by another granular version or commit (both are named in the "
       "metadata)"},
      {"fresh", &O::fresh, "discard the checkpoint of an interrupted run and start again"},
      {"skip_failed", &O::skip_failed,
       "leave a realization that fails numerically out of the means (counted in the metadata) instead of stopping "
       "at it"},
      {"one_at_a_time", &O::one_at_a_time,
       "integrate the realizations one at a time instead of side by side in vector lanes (the same results to the "
       "last bit; the lanes are faster)"}};
  return table;
}

void validate(const RunOptions& o) {
  if (o.threads < 0 || o.threads > 4096)
    // append, not " " + to_string(…): GCC 12's -Wrestrict misfires on the latter in some unity batches.
    throw InvalidInput("threads", std::string(" ").append(std::to_string(o.threads)).append(": 0 (every core) to 4096"));
  if (o.resuming() && o.fresh)
    throw InvalidInput("fresh", ": not with `resume` (continue, or start again: one of them)");
  if (o.resuming() && o.checkpoint.empty())
    throw InvalidInput("resume", ": needs `checkpoint` (the file or prefix of the interrupted run)");
}

}  // namespace granular
