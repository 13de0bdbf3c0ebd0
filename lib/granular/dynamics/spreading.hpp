#pragma once
// One realization of energy spreading (docs/physics.md, "Nonlinear dynamics") as the tools run it: a kicked chain
// integrated to T, with the observables of the `spreading` tool chosen by a flat config and returned in one result. A
// thin layer over spread() and the observers (spread.hpp, observers.hpp), which is what a program measuring something
// else should use. A pure function of (chain, initial state, config), so ensembles can run it per realization and
// reduce in index order.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "granular/dynamics/damping.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/integrator.hpp"
#include "granular/dynamics/observers.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/sampling.hpp"
#include "granular/dynamics/spread.hpp"
#include "granular/dynamics/state.hpp"
#include "granular/dynamics/tangent_map.hpp"

namespace granular {

struct SpreadingConfig {
  ForceLawKind force_law = ForceLawKind::hertz;
  Integrator integrator{};                          ///< SABA2C unless told otherwise
  double duration = 1e-2;                           ///< T [s], a whole number of steps
  double time_step = 1e-6;                          ///< τ [s]
  std::size_t samples = 100;                        ///< times of t, m̃2, P⁻¹, energy error (≥ 2) outside `dense`
  Sampling sampling = Sampling::logarithmic;        ///< log: τ … T; uniform: 0 … T
  DenseGrid dense;                                  ///< a uniform grid replacing the samples inside it (the fit window)
  std::size_t site = static_cast<std::size_t>(-1);  ///< excited bead n0 of m̃2 (0-based); default the centre
  ActiveWindow window;                              ///< ignored by the reference integrator
  std::vector<std::size_t> force_sites;             ///< 0-based beads whose force is recorded
  std::size_t force_samples = 1000;                 ///< uniform times of those forces
  std::size_t map_samples = 0;                      ///< uniform times of the energy map; 0 = none
  std::size_t map_stride = 1;                       ///< beads summed per map column
  std::size_t spectrum_samples = 0;                 ///< uniform samples of u (or v) for g(ν); 0 = none
  SpectrumSource spectrum_source = SpectrumSource::displacement;
  double wall_warning = 1e-10;       ///< flag when (E_first + E_last)/H0 exceeds it
  double max_energy_error = 1e-3;    ///< guard on |H(t)−H0|/H0 at the samples; 0 = unwatched
  bool stop_on_energy_error = true;  ///< past the guard: stop (NumericalError) or only record it
  Damping damping;          ///< dissipation (damping.hpp); none by default. Then energy_error is of H + dissipated
  LyapunovConfig lyapunov;  ///< X1(t) by the tangent map (tangent_map.hpp); conservative schemes only
  std::size_t deviation_samples = 0;  ///< uniform times of the deviation-vector distribution; 0 = none
};

/// The integration part of a config, and the settings of its observers.
IntegrationConfig integration_config(const SpreadingConfig& config);
EnergySpreadObserver::Settings energy_spread_settings(const SpreadingConfig& config);

/// Throws InvalidInput naming the parameter (time_step, duration, samples, forces_at, …) on a bad config.
void validate(const SpreadingConfig& config, std::size_t beads);

struct SpreadingResult {
  std::vector<double> t;             ///< sample times [s]
  std::vector<double> m2;            ///< m̃2 about the excited bead n0 [bead²] (the paper's)
  std::vector<double> m2_centroid;   ///< m̃2 about the energy centroid [bead²]
  std::vector<double> ipr;           ///< P⁻¹ of the energy
  std::vector<double> energy_error;  ///< |H(t) + dissipated(t) − H0| / H0
  std::vector<double> dissipated;    ///< energy removed by damping by t [J]; empty without damping
  std::vector<double> mle;           ///< X1(t) [1/s] at the sample times; empty without lyapunov
  std::vector<double> deviation_t;   ///< times of the deviation-vector distribution rows
  std::vector<double> deviation;     ///< rows × N, row-major: share of ‖w‖² on each bead
  double initial_energy = 0;
  double max_energy_error = 0;
  State final_state;
  std::vector<double> final_energy;         ///< E_n(T)
  std::vector<double> final_force;          ///< bead forces at T [N]
  std::vector<double> force_t;              ///< times of the force series
  std::vector<std::vector<double>> forces;  ///< [site][sample]
  std::vector<double> map_t;                ///< times of the energy map rows
  std::vector<double> map_energy;           ///< rows × map_columns, row-major
  std::size_t map_columns = 0;
  std::vector<double> spectrum_khz, spectrum;  ///< g(ν) normalized to max 1, of config.spectrum_source
  double wall_energy = 0;                      ///< max over samples of (E_first + E_last)/H0
  bool reached_walls = false;                  ///< wall_energy > config.wall_warning
  double energy_guard_time = -1;  ///< first sample time past max_energy_error (when not stopping); -1: never
  std::uint64_t steps = 0, bond_updates = 0;
  std::size_t window_begin = 0, window_end = 0;  ///< final active window
  double seconds = 0;                            ///< wall time of the integration
};

/// spread() with the observers `config` asks for (energy spread and final state always; forces,
/// energy map, spectral density when their sites or samples are given), packed into one result.
SpreadingResult run_spreading(const Chain& chain, const State& initial, const SpreadingConfig& config);

/// The sample steps of the energy spread of a run: those of sample_steps() outside the dense
/// grid, and the grid's own steps inside it; sorted, without duplicates.
std::vector<std::uint64_t> sample_steps(const SpreadingConfig& config);

}  // namespace granular
