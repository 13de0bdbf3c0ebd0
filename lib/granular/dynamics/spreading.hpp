#pragma once
// One realization of energy spreading (SPEC §4): integrate a chain from an initial state to T,
// measuring on a schedule of exact multiples of τ. A pure function of (chain, initial state,
// config), so ensembles can run it per realization and reduce in index order.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "granular/dynamics/damping.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/state.hpp"
#include "granular/dynamics/tangent_map.hpp"

namespace granular {

enum class Sampling { logarithmic, uniform };
Sampling parse_sampling(const std::string& name);

/// A uniform grid of sample times, [begin, end] every `step` (all multiples of τ): where the
/// exponents are fitted and L_d is taken, so that they see the curve densely (the paper
/// computes L_d "where we discretize time as in our numerical integration"). Empty when
/// end ≤ begin.
struct DenseGrid {
  double begin = 0, end = 0;  ///< [s]
  double step = 1e-5;         ///< [s], a whole number of time steps
  bool empty() const { return !(end > begin); }
};

/// What g(ν) transforms (SPEC §4). The paper's is the displacement; after a velocity kick in the
/// sonic vacuum every bead the pulse has passed keeps a permanent displacement, a step in u_n(t)
/// whose power ∝ 1/ν² buries the vibrations under a peak at 0 Hz. The velocity is the step's
/// derivative (a pulse, white), so its spectrum shows the vibrations themselves.
enum class SpectrumSource { displacement, velocity };
SpectrumSource parse_spectrum_source(const std::string& name);  ///< "displacement" | "velocity"
std::string to_string(SpectrumSource source);

struct SpreadingConfig {
  ForceLawKind force_law = ForceLawKind::hertz;
  std::string integrator = "saba2c";                ///< saba2c | saba2 | aba864 | srkn14a | reference
  double duration = 1e-2;                           ///< T [s], a whole number of steps
  double time_step = 1e-6;                          ///< τ [s]
  std::size_t samples = 100;                        ///< times of t, m̃2, P⁻¹, energy error (≥ 2) outside `dense`
  Sampling sampling = Sampling::logarithmic;        ///< log: τ … T; uniform: 0 … T
  DenseGrid dense;                                  ///< a uniform grid replacing the samples inside it (the fit window)
  std::size_t site = static_cast<std::size_t>(-1);  ///< excited bead n0 of m̃2 (0-based); default the centre
  ActiveWindow window;                              ///< ignored by the reference integrator
  ReferenceTolerance reference{1e-15, 1e-15, 0.01e-6};  ///< step capped at 0.01 µs (contacts open)
  std::vector<std::size_t> force_sites;                 ///< 0-based beads whose force is recorded
  std::size_t force_samples = 1000;                     ///< uniform times of those forces
  std::size_t map_samples = 0;                          ///< uniform times of the energy map; 0 = none
  std::size_t map_stride = 1;                           ///< beads summed per map column
  std::size_t spectrum_samples = 0;                     ///< uniform samples of u (or v) for g(ν); 0 = none
  SpectrumSource spectrum_source = SpectrumSource::displacement;
  double wall_warning = 1e-10;       ///< flag when (E_first + E_last)/H0 exceeds it
  double max_energy_error = 1e-3;    ///< guard on |H(t)−H0|/H0 at the samples; 0 = unwatched
  bool stop_on_energy_error = true;  ///< past the guard: stop (NumericalError) or only record it
  Damping damping;          ///< dissipation (damping.hpp); none by default. Then energy_error is of H + dissipated
  LyapunovConfig lyapunov;  ///< X1(t) by the tangent map (tangent_map.hpp); conservative schemes only
  std::size_t deviation_samples = 0;  ///< uniform times of the deviation-vector distribution; 0 = none
};

/// Throws InvalidInput naming the option (--T, --dt, --samples, …) on a bad config.
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

SpreadingResult run_spreading(const Chain& chain, const State& initial, const SpreadingConfig& config);

/// Step numbers of `count` log-spaced (1 … total, duplicates removed) or uniform
/// (0, stride, 2·stride …, stride = ⌊total/(count−1)⌋) samples.
std::vector<std::uint64_t> sample_steps(std::uint64_t total, std::size_t count, Sampling sampling);

/// The sample steps of a run: those of sample_steps() outside the dense grid, and the grid's
/// own steps (begin, begin + step, …, and end) inside it; sorted, without duplicates.
std::vector<std::uint64_t> sample_steps(const SpreadingConfig& config);

}  // namespace granular
