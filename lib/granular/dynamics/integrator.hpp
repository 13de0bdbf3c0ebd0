#pragma once
// How a run advances the chain, as a value: a splitting scheme (SABA2C by default, scheme.hpp)
// or the adaptive Odeint RKF78 reference with its tolerances (propagator.hpp). The library takes
// this value; only front ends turn a word ("saba2c", "reference") into one (parse_integrator).
//
//   granular::IntegrationConfig config{.duration = 1e-3, .integrator = granular::aba864()};
//   config.integrator = granular::Integrator::odeint();  // the slow cross-check
#include <memory>
#include <string>
#include <string_view>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/dynamics/state.hpp"

namespace granular {

struct Integrator {
  Integrator() = default;
  /// A splitting scheme: Integrator i = granular::srkn14a();
  Integrator(SplittingScheme splitting) : scheme(std::move(splitting)) {}  // NOLINT(google-explicit-constructor)
  /// Boost.Odeint's controlled RKF78 at `tolerance`; by default 1e-15 and its step capped at
  /// 0.01 µs, so that it resolves contacts opening and closing.
  static Integrator odeint(const ReferenceTolerance& tolerance = {1e-15, 1e-15, 0.01e-6});

  SplittingScheme scheme = saba2c();                    ///< used unless `reference`
  bool reference = false;                               ///< the Odeint reference instead of the scheme
  ReferenceTolerance tolerance{1e-15, 1e-15, 0.01e-6};  ///< of the reference

  /// "saba2c", "aba864", … or "reference": the word parse_integrator reads back.
  std::string name() const { return reference ? "reference" : scheme.name; }
};

/// saba2c | saba2 | aba864 | srkn14a | reference (any case); throws InvalidInput naming `integrator`.
Integrator parse_integrator(std::string_view name);

/// The propagator of `integrator` on `law` from `initial` with step τ; `window` is the splitting
/// stepper's active window (the reference integrates the whole chain).
std::unique_ptr<Propagator> make_propagator(const Integrator& integrator, const ForceLaw& law, const Chain& chain,
                                            double time_step, const State& initial, const ActiveWindow& window = {});

}  // namespace granular
