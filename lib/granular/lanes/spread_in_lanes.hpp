#pragma once
// spread() (spread.hpp) for several chains of one length at once, side by side in vector lanes
// (lane_propagator.hpp; lane_tangent_propagator.hpp with the tangent map): what an ensemble uses to run
// LanePropagator::width() realizations for the cost of about one. Each chain gets its own observers, called exactly as
// spread() would call them, and every number they see is the one spread() would show them: the results are the same
// bits as running the chains one at a time.
//
//   std::vector<granular::EnergySpreadObserver> energy(chains.size());
//   std::vector<std::vector<granular::Observer*>> observers;
//   for (auto& e : energy) observers.push_back({&e});
//   auto runs = granular::spread_in_lanes(chains, kicks, {.duration = 1e-3}, observers);
#include <exception>
#include <span>
#include <vector>

#include "granular/dynamics/spread.hpp"

namespace granular {

/// Whether spread_in_lanes can run `config`: a splitting scheme without damping (the reference
/// integrator and damped runs go one chain at a time, with spread()). With the tangent map
/// (config.lyapunov) each lane carries its deviation vector (lane_tangent_propagator.hpp) and its
/// observers see it in Snapshot::tangent, as spread()'s do.
bool runs_in_lanes(const IntegrationConfig& config);

/// One chain's run in a batch.
struct LaneRun {
  RunInfo info;  ///< its `seconds` is the batch's integration time
  /// What stopped this chain's run (an observer's NumericalError), rethrown by the caller as it
  /// likes; the other chains ran on. Null when the run reached T.
  std::exception_ptr failure;
};

/// Runs chains[l] from initials[l] with observers[l], for l < chains.size() ≤
/// LanePropagator::width(), every chain of one length. Throws InvalidInput as spread() does (for
/// any chain, before any step), and when !runs_in_lanes(config).
std::vector<LaneRun> spread_in_lanes(std::span<const Chain> chains, std::span<const State> initials,
                                     const IntegrationConfig& config, std::span<const std::vector<Observer*>> observers);

}  // namespace granular
