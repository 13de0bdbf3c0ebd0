#pragma once
// Advancing a chain in time, whatever the method: the common interface of the symplectic
// splitting stepper and the Odeint reference. Time moves in whole steps of τ, so samples
// taken after advance() sit on exact multiples of τ for every method.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/dynamics/state.hpp"

namespace granular {

/// Integrate only the disturbed part of the chain (docs/physics.md, "Nonlinear dynamics" performance rule, DESIGN.md).
///
/// The window [begin, end) of beads starts as the non-zero part of the initial state widened
/// by `guard` beads on each side; outside it u = v = 0 exactly and no work is done. After every
/// step, if any bead in the outermost `guard` beads of the window has kinetic energy
/// m v²/2 > threshold · H0 (H0 the initial total energy), that side grows by `guard` beads.
/// A step spreads a disturbance by at most one bead per kick (two per corrector), far less
/// than `guard`, so everything above the threshold always stays inside the window; what is
/// cut off is below 1e-15 of the amplitude (threshold 1e-30 in energy) and its effect on
/// the final state is below 1e-12 relative (tests/dynamics: active window on vs off).
struct ActiveWindow {
  bool enabled = true;
  double threshold = 1e-30;  ///< relative kinetic energy that makes the window grow
  std::size_t guard = 64;    ///< beads checked at each edge, and added when it grows
};

class Propagator {
 public:
  virtual ~Propagator() = default;
  /// Advances by `steps` × τ.
  virtual void advance(std::size_t steps) = 0;
  virtual std::span<const double> displacement() const = 0;
  virtual std::span<const double> velocity() const = 0;
  virtual double time_step() const = 0;
  virtual std::uint64_t steps_done() const = 0;
  double time() const { return static_cast<double>(steps_done()) * time_step(); }
  /// Beads [window_begin, window_end) may be non-zero; all others are exactly at rest.
  virtual std::size_t window_begin() const { return 0; }
  virtual std::size_t window_end() const { return displacement().size(); }
  /// Bond force evaluations so far (one bond, one force; the speed measure).
  virtual std::uint64_t bond_updates() const = 0;
  /// Energy removed by dissipation so far [J] (damping.hpp); 0 for a conservative method.
  virtual double dissipated_energy() const { return 0; }
  State state() const;
};

/// Throws InvalidInput unless τ is finite and > 0 and `initial` is finite and fits the chain.
void validate_propagation(const Chain& chain, double time_step, const State& initial);

/// The splitting scheme on `law`, from `initial` at t = 0 with step τ.
std::unique_ptr<Propagator> make_splitting_propagator(const ForceLaw& law, const Chain& chain,
                                                      const SplittingScheme& scheme, double time_step,
                                                      const State& initial, const ActiveWindow& window = {});

/// Tolerances of the reference integrator, applied to the state scaled to O(1) (u by its
/// initial amplitude ℓ, v by ℓ/1µs).
struct ReferenceTolerance {
  double absolute = 1e-15;
  double relative = 1e-15;
  double max_step = 0;  ///< largest step [s]; 0: no limit
};

/// Boost.Odeint's controlled runge_kutta_fehlberg78 at tight tolerances: the cross-check.
/// It samples at the same multiples of τ, but its own steps are adaptive.
std::unique_ptr<Propagator> make_reference_propagator(const ForceLaw& law, const Chain& chain, double time_step,
                                                      const State& initial, const ReferenceTolerance& tolerance = {});

}  // namespace granular
