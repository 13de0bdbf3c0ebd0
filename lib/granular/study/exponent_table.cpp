#include "granular/study/exponent_table.hpp"

#include <algorithm>

#include "granular/ensemble/checkpoint_log.hpp"

namespace granular {

std::vector<TransportCase> exponent_cases(const ExponentTableConfig& config) {
  std::vector<TransportCase> cases;
  for (Kick kick : config.kicks)
    for (double f0 : config.precompressions)
      for (Disorder chain : config.chains) {
        TransportCase c = config.base;
        c.kick = kick;
        c.precompression = f0;
        c.disorder = chain;
        if (chain == Disorder::homogeneous) c.realizations = 1;  // every realization is the same chain
        const bool profile = std::find(config.profile_precompressions.begin(), config.profile_precompressions.end(),
                                       f0) != config.profile_precompressions.end();
        c.profile_realizations = profile ? std::min(config.profile_realizations, c.realizations) : 0;
        cases.push_back(c);
      }
  return cases;
}

std::vector<ExponentCell> run_exponent_table(const ExponentTableConfig& config, const ExponentRunOptions& options) {
  const auto cases = exponent_cases(config);
  for (const auto& c : cases) validate(c);  // every case checked before the first one runs
  std::size_t total = 0;
  for (const auto& c : cases) total += c.realizations;
  ProgressMeter own(total, "exponents", options.meter ? 0 : options.progress);
  std::vector<ExponentCell> cells;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    StudyRunOptions run;
    run.threads = options.threads;
    run.progress = options.meter ? options.meter : &own;
    run.cancelled = options.cancelled;
    if (!options.checkpoint_prefix.empty()) {
      run.checkpoint = options.checkpoint_prefix + "." + std::to_string(i);
      // A case not started before the interruption has no log yet: it simply starts.
      run.resume = options.resume && CheckpointLog::exists(run.checkpoint);
    }
    cells.push_back({cases[i], run_transport_study(cases[i], run)});
  }
  own.finish();
  return cells;
}

}  // namespace granular
