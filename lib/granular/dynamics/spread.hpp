#pragma once
// One run of the nonlinear dynamics (docs/physics.md, "Nonlinear dynamics"): integrate a chain from an initial state to T and
// let observers (observer.hpp, observers.hpp) measure it. The driver owns time and the
// integrator; what is measured is the observers' business. A pure function of (chain, initial
// state, config) — observers only look — so ensembles run it per realization.
//
//   auto chain = granular::anderson({.N = 2501});
//   granular::EnergySpreadObserver spread;                      // m̃2, P⁻¹, energy error
//   const granular::RunInfo info = granular::spread(
//       chain, granular::velocity_kick(chain, 1250, 8e-3), {.duration = 1e-3}, spread);
#include <concepts>
#include <cstdint>
#include <span>

#include "granular/dynamics/damping.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/integrator.hpp"
#include "granular/dynamics/observer.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/state.hpp"
#include "granular/dynamics/tangent_map.hpp"

namespace granular {

struct IntegrationConfig {
  double duration = 1e-2;   ///< T [s], a whole number of steps
  double time_step = 1e-6;  ///< τ [s]
  ForceLawKind force_law = ForceLawKind::hertz;
  Integrator integrator{};  ///< SABA2C unless told otherwise
  ActiveWindow window{};    ///< ignored by the reference integrator
  /// Dissipation (damping.hpp), split with the scheme; none by default. The whole chain is then
  /// integrated (no active window) and Snapshot::dissipated counts the energy removed.
  Damping damping{};
  /// The tangent map (tangent_map.hpp): a deviation vector carried along by the same scheme, for
  /// X1(t) (LyapunovObserver). Conservative schemes only; whole chain.
  LyapunovConfig lyapunov{};
  /// Bead (0-based) where the initial deviation vector sits; default the centre.
  std::size_t deviation_site = static_cast<std::size_t>(-1);
};
/// Throws InvalidInput naming the field (time_step, duration, window_threshold, damping_time,
/// kk_gamma, integrator, lyapunov) on a bad config.
void validate(const IntegrationConfig& config);
/// The first of those checks: τ and T each finite and > 0 (naming time_step or duration), without
/// the checks of T on τ's grid — what a stability limit on τ needs before it can be judged.
void validate_step_and_duration(const IntegrationConfig& config);

/// How to step: the propagator `config` asks for on `law` from `initial` — the tangent map (a
/// TangentPropagator) when config.lyapunov is on, the damped splitting when config.damping is,
/// else the scheme with its active window or the Odeint reference. The one place that chooses.
std::unique_ptr<Propagator> make_propagator(const IntegrationConfig& config, const ForceLaw& law, const Chain& chain,
                                            const State& initial);

/// The deviation vector a run with the tangent map starts from (config.lyapunov on): δu = 1 and
/// δv = 1/t_unit on config.deviation_site, or the centre bead when that is past the chain.
State starting_deviation(const IntegrationConfig& config, std::size_t beads);

/// What the run did, besides what the observers measured.
struct RunInfo {
  double initial_energy = 0;  ///< H(0) [J]
  std::uint64_t steps = 0, bond_updates = 0;
  std::size_t window_begin = 0, window_end = 0;  ///< final active window, beads [begin, end)
  double seconds = 0;                            ///< wall time of the integration alone
};

/// Integrates to T, calling each observer at the steps it scheduled (the union of all schedules,
/// in time order; at a shared step in the order given) and finish() at T. Throws InvalidInput on
/// a bad config, initial state or observer setting, before any step; NumericalError when an
/// observer stops the run. Observers are never null.
RunInfo spread(const Chain& chain, const State& initial, const IntegrationConfig& config,
               std::span<Observer* const> observers);

template <class... Observers>
requires(std::derived_from<Observers, Observer>&&...) RunInfo
    spread(const Chain& chain, const State& initial, const IntegrationConfig& config, Observers&... observers) {
  Observer* list[] = {static_cast<Observer*>(&observers)..., nullptr};
  return spread(chain, initial, config, std::span<Observer* const>(list, sizeof...(Observers)));
}

}  // namespace granular
