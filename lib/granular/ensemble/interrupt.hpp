#pragma once
// Ctrl-C as a clean stop of a long run. After stop_on_interrupt, SIGINT and SIGTERM only ask the
// run to stop: pass the result as RunOptions::cancelled (run_options.hpp). The realizations in
// flight finish and are checkpointed, then the run ends with granular::Cancelled, and the same
// run resumed later computes only the rest. A second Ctrl-C stops at once (the checkpoint stays
// consistent: every line of it is flushed whole or ignored).
#include <functional>
#include <string>

namespace granular {

/// Installs the handlers; the first signal prints "\n<program>: stopping once the realizations
/// in flight are saved (Ctrl-C again: stop at once)" on stderr. Returns whether one has come.
std::function<bool()> stop_on_interrupt(const std::string& program);

}  // namespace granular
