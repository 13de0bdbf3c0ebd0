#pragma once
// One realization of energy spreading (docs/physics.md, "Nonlinear dynamics") as the `spreading` tool and Python run
// it: a kicked chain integrated to T by spread() (dynamics/spread.hpp) with the energy spread and the final state
// always observed, and the optional observers (dynamics/observers.hpp) each switched on by its own settings; everything
// measured comes back in one result. A program measuring something else composes spread() and the observers itself.
// A pure function of (chain, initial state, run), so ensembles can run it per realization and reduce in index order.
//
//   granular::SpreadingRunConfig run;
//   run.integration.duration = 1e-3;                        // T [s]
//   run.forces.sites = {600, 630};                          // force series on two beads
//   run.energy_map = granular::EnergyMapObserver::Settings{.samples = 200, .stride = 5};
//   const granular::SpreadingResult r = granular::run_spreading(chain, initial, run);
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "granular/chaos/covariant_vectors.hpp"
#include "granular/chaos/lyapunov_spectrum.hpp"
#include "granular/dynamics/observers.hpp"
#include "granular/dynamics/spread.hpp"
#include "granular/dynamics/state.hpp"
#include "granular/optional_settings.hpp"

namespace granular {

/// What one spreading run integrates and what it measures, each observer's settings with it.
struct SpreadingRunConfig {
  /// T, τ, force law, integrator, active window, damping and tangent map. Its deviation_site is
  /// not read: the deviation vector starts on the excited bead, spread.site.
  IntegrationConfig integration{};
  /// m̃2, P⁻¹ and the energy error: sample times, dense grid, excited bead n0 (default the centre), guards.
  EnergySpreadObserver::Settings spread{};
  ForceObserver::Settings forces{};                                ///< bead forces; no sites: none recorded
  OptionalSettings<EnergyMapObserver::Settings> energy_map{};      ///< E_n(t) map; off: none
  OptionalSettings<SpectralDensityObserver::Settings> spectrum{};  ///< g(ν); off: none
  std::size_t deviation_samples = 0;  ///< uniform times of the deviation vector (integration.lyapunov on); 0 = none
  /// k deviation vectors of a Lyapunov spectrum (lyapunov_spectrum.hpp) on the same orbit, 1 ≤ k ≤ 2N,
  /// re-orthonormalized every integration.lyapunov.renormalize_every steps (integration.lyapunov on); 0 = none.
  std::size_t lyapunov_vectors = 0;
  /// k covariant Lyapunov vectors (covariant_vectors.hpp) on the same orbit, 1 ≤ k ≤ 2N, at the sample
  /// times in [transient, T], the backward phase from T + transient (integration.lyapunov on); 0 = none.
  std::size_t covariant_vectors = 0;
  std::optional<double> covariant_transient{};  ///< forward and backward transient [s]; none: T/2
};

/// The integration of a run, its deviation vector on the excited bead; and the settings of X1(t)'s observer.
IntegrationConfig integration_config(const SpreadingRunConfig& run);
LyapunovObserver::Settings lyapunov_settings(const SpreadingRunConfig& run);
/// The spectrum's settings: run.lyapunov_vectors vectors, the tangent map's interval and norm.
LyapunovSpectrumConfig lyapunov_spectrum_config(const SpreadingRunConfig& run);

/// The CLVs' settings: run.covariant_vectors vectors, the tangent map's interval and norm, both
/// transients the steps nearest run.covariant_transient (none: T/2).
CovariantVectorsConfig covariant_config(const SpreadingRunConfig& run);
/// The CLVs' samples: those of sample_steps(run) from the forward transient on, counted from its end.
std::vector<std::uint64_t> covariant_sample_steps(const SpreadingRunConfig& run);

/// Throws InvalidInput naming the parameter (time_step, duration, samples, forces_at, …) on a bad run.
void validate(const SpreadingRunConfig& run, std::size_t beads);

struct SpreadingResult {
  std::vector<double> t;             ///< sample times [s]
  std::vector<double> m2;            ///< m̃2 about the excited bead n0 [bead²] (the paper's)
  std::vector<double> m2_centroid;   ///< m̃2 about the energy centroid [bead²]
  std::vector<double> ipr;           ///< P⁻¹ of the energy
  std::vector<double> energy_error;  ///< |H(t) + dissipated(t) − H0| / H0
  std::vector<double> dissipated;    ///< energy removed by damping by t [J]; empty without damping
  std::vector<double> mle;           ///< X1(t) [1/s] at the sample times; empty without the tangent map
  std::vector<double> deviation_t;   ///< times of the deviation-vector distribution rows [s]
  std::vector<double> deviation;     ///< rows × N, row-major: share of ‖w‖² on each bead
  LyapunovSeries lyapunov;           ///< λ_j(t), GALI_j(t), SALI(t) at the times t; empty without lyapunov_vectors
  CovariantVectors covariant;        ///< the CLVs at covariant_sample_steps; empty without covariant_vectors
  double initial_energy = 0;         ///< H(0) [J]
  double max_energy_error = 0;       ///< the largest of energy_error
  State final_state;
  std::vector<double> final_energy;            ///< E_n(T) [J]
  std::vector<double> final_force;             ///< bead forces at T [N]
  std::vector<double> force_t;                 ///< times of the force series [s]
  std::vector<std::vector<double>> forces;     ///< [site][sample] [N]
  std::vector<double> map_t;                   ///< times of the energy map rows [s]
  std::vector<double> map_energy;              ///< rows × map_columns, row-major [J]
  std::size_t map_columns = 0;                 ///< 0 without a map
  std::vector<double> spectrum_khz, spectrum;  ///< g(ν) normalized to max 1 of run.spectrum->source; ν in kHz
  double wall_energy = 0;                      ///< max over samples of (E_first + E_last)/H0
  bool reached_walls = false;                  ///< wall_energy > run.spread.wall_warning
  double energy_guard_time = -1;  ///< first sample time past the energy guard (when not stopping) [s]; -1: never
  std::uint64_t steps = 0, bond_updates = 0;
  std::size_t window_begin = 0, window_end = 0;  ///< final active window, beads [begin, end)
  double seconds = 0;                            ///< wall time of the integration
};

/// spread() with the energy spread, the final state, the force series, and whichever of the energy map,
/// spectral density and X1(t) (with its deviation vector) `run` switches on, packed into one result.
/// With run.lyapunov_vectors, the spectrum and the alignment indices are integrated after the run,
/// from the same initial state by the same scheme: the same orbit once more, the observers' run untouched.
/// So are the CLVs with run.covariant_vectors: that orbit to rounding (their forward transient is one
/// advance, the run stops at its samples), carried on past T by the backward transient.
SpreadingResult run_spreading(const Chain& chain, const State& initial, const SpreadingRunConfig& run);

/// The sample steps of the energy spread of a run: those of sample_steps() outside the dense
/// grid, and the grid's own steps inside it; sorted, without duplicates.
std::vector<std::uint64_t> sample_steps(const SpreadingRunConfig& run);

}  // namespace granular
