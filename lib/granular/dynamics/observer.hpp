#pragma once
// Observers measure a run, as Boost.Odeint's do: the driver (spread(), spread.hpp) owns time and
// the integrator; each observer says when it wants to look at the chain, keeps what it measures
// and owns its settings. A new observable is a new observer — the driver does not change.
//
//   struct Peak : granular::Observer {            // the largest |v_n| every 100 steps
//     std::vector<double> t, v_max;
//     std::vector<std::uint64_t> schedule(const granular::RunPlan& plan) override {
//       std::vector<std::uint64_t> s;
//       for (std::uint64_t k = 0; k <= plan.total_steps; k += 100) s.push_back(k);
//       return s;
//     }
//     void observe(const granular::Snapshot& now) override {
//       double m = 0;
//       for (double v : now.v) m = std::max(m, std::abs(v));
//       t.push_back(now.t), v_max.push_back(m);
//     }
//   };
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/state.hpp"
#include "granular/model/chain.hpp"

namespace granular {

class TangentPropagator;

/// What an observer learns before the run: the chain's size and the time grid.
struct RunPlan {
  std::size_t beads = 0;
  std::uint64_t total_steps = 0;  ///< T / τ
  double time_step = 0;           ///< τ [s]
  double duration = 0;            ///< T [s] as asked (total_steps · τ up to rounding)
};

/// The chain at one observed time. Beads outside [window_begin, window_end) are exactly at rest
/// (the active window, propagator.hpp). Valid only during the call that receives it.
class Snapshot {
 public:
  Snapshot(const Chain& chain, const ForceLaw& law, double initial_energy)
      : chain_(chain), law_(law), initial_energy_(initial_energy) {}
  Snapshot(const Snapshot&) = delete;
  Snapshot& operator=(const Snapshot&) = delete;

  std::uint64_t step = 0;        ///< steps done
  double t = 0;                  ///< time [s] = step · τ
  std::span<const double> u, v;  ///< displacements [m], velocities [m/s] of every bead
  std::size_t window_begin = 0, window_end = 0;
  double dissipated = 0;  ///< energy removed by damping so far [J]; 0 for a conservative run
  /// The deviation vector's propagator when the run carries the tangent map, else null.
  const TangentPropagator* tangent = nullptr;

  const Chain& chain() const { return chain_; }
  const ForceLaw& law() const { return law_; }
  double initial_energy() const { return initial_energy_; }  ///< H(0) [J]
  /// Site energies E_n [J] (docs/physics.md, "Nonlinear dynamics"), computed once per time however many observers ask.
  std::span<const double> energy() const;
  State state() const;  ///< a copy of u and v
  /// The driver moved the state on: forget the cached energies.
  void moved() { energy_ready_ = false; }

 private:
  const Chain& chain_;
  const ForceLaw& law_;
  double initial_energy_;
  mutable std::vector<double> energy_;
  mutable bool energy_ready_ = false;
};

class Observer {
 public:
  virtual ~Observer() = default;
  /// Called once before the run: check the settings against the run (InvalidInput naming the
  /// parameter), forget any earlier run, and return the steps (0 … total_steps) to observe.
  virtual std::vector<std::uint64_t> schedule(const RunPlan& plan) = 0;
  /// Called at every scheduled step, in time order. May throw NumericalError to stop the run.
  virtual void observe(const Snapshot& now) = 0;
  /// Called once at T, after the last observe().
  virtual void finish(const Snapshot& /*at_T*/) {}
};

}  // namespace granular
