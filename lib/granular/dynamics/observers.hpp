#pragma once
// The observables of a spreading run (docs/physics.md, "Nonlinear dynamics"), each an Observer (observer.hpp) owning
// its settings and what it measured:
//
//   granular::EnergySpreadObserver spread({.samples = 100});  // m̃2 (both centres), P⁻¹, energy error
//   granular::ForceObserver forces({.sites = {600, 630, 660}});  // bead forces at three beads
//   granular::spread(chain, initial, {.duration = 1e-3}, spread, forces);
//   // spread.t, spread.m2, spread.ipr, forces.forces[0] …
//
// Sites are 0-based bead indices; times are whole steps of τ. Errors name the parameters as the
// tools and Python call them (`samples`, `forces_at`, `map_stride`, …).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "granular/dynamics/observer.hpp"
#include "granular/dynamics/sampling.hpp"
#include "granular/dynamics/state.hpp"

namespace granular {

/// m̃2 about the excited bead n0 (the paper's) and about the energy centroid, P⁻¹ and the relative
/// energy error |H(t) + dissipated(t) − H0|/H0 at the sample times (dissipated: 0 without damping), with the run's
/// guards: a non-finite state stops the run (NumericalError); an energy error past `max_energy_error` stops it or is
/// recorded; energy reaching the walls is recorded.
class EnergySpreadObserver final : public Observer {
 public:
  struct Settings {
    std::size_t samples = 100;                                   ///< sample times outside `dense` (≥ 2)
    Sampling sampling = Sampling::logarithmic;                   ///< log: τ … T; uniform: 0 … T
    DenseGrid dense{};                                           ///< a uniform grid replacing the samples inside it
    std::size_t site = std::numeric_limits<std::size_t>::max();  ///< excited bead n0 of m̃2; default the centre
    double max_energy_error = 1e-3;                              ///< guard on |H(t)−H0|/H0; 0 = unwatched
    bool stop_on_energy_error = true;  ///< past the guard: stop (NumericalError) or only record it
    double wall_warning = 1e-10;       ///< flag when (E_first + E_last)/H0 exceeds it
    /// Throws InvalidInput naming `samples`, `site`, `fit` or `fit_step`.
    void validate(const RunPlan& plan) const;
  };
  EnergySpreadObserver() = default;
  explicit EnergySpreadObserver(const Settings& settings) : settings_(settings) {}
  std::vector<std::uint64_t> schedule(const RunPlan& plan) override;
  void observe(const Snapshot& now) override;
  const Settings& settings() const { return settings_; }

  std::vector<double> t;             ///< sample times [s]
  std::vector<double> m2;            ///< m̃2 about the excited bead n0 [bead²] (the paper's)
  std::vector<double> m2_centroid;   ///< m̃2 about the energy centroid [bead²]
  std::vector<double> ipr;           ///< P⁻¹ of the energy, in (0, 1]
  std::vector<double> energy_error;  ///< |H(t) + dissipated(t) − H0| / H0
  std::vector<double> dissipated;    ///< energy removed by damping by t [J] (zeros without damping)
  double max_energy_error = 0;       ///< the largest of energy_error
  double wall_energy = 0;            ///< max over samples of (E_first + E_last)/H0
  double energy_guard_time = -1;     ///< first sample past the guard when not stopping [s]; -1: never
  bool reached_walls() const { return wall_energy > settings_.wall_warning; }

 private:
  Settings settings_;
  std::size_t site_ = 0;  // n0 of this run
};

/// The force on chosen beads (the mean of its two contact forces, what a sensor embedded in the
/// bead reads, docs/physics.md, "Nonlinear dynamics") at uniform times 0 … T.
class ForceObserver final : public Observer {
 public:
  struct Settings {
    std::vector<std::size_t> sites{};  ///< 0-based beads
    std::size_t samples = 1000;        ///< uniform times 0 … T (≥ 2)
    /// Throws InvalidInput naming `forces_at` or `force_samples`.
    void validate(const RunPlan& plan) const;
  };
  explicit ForceObserver(Settings settings) : settings_(std::move(settings)) {}
  std::vector<std::uint64_t> schedule(const RunPlan& plan) override;
  void observe(const Snapshot& now) override;
  const Settings& settings() const { return settings_; }

  std::vector<double> t;                    ///< sample times [s]
  std::vector<std::vector<double>> forces;  ///< [site][sample] [N]

 private:
  Settings settings_;
  std::vector<double> buffer_;
};

/// The spatiotemporal energy map E_n(t_k) at uniform times 0 … T, `stride` beads summed per column.
class EnergyMapObserver final : public Observer {
 public:
  struct Settings {
    std::size_t samples = 500;  ///< uniform times 0 … T (≥ 2)
    std::size_t stride = 1;     ///< beads per column (≥ 1)
    /// Throws InvalidInput naming `map_samples` or `map_stride`; `map_samples` also when the map
    /// needs more than half the memory this process may use (the least of RAM, its cgroup's limit
    /// and ulimit -v: detail/memory_limit.hpp), before the run rather than hours into it.
    void validate(const RunPlan& plan) const;
    double map_times(const RunPlan& plan) const;    ///< rows: min(samples, steps + 1)
    double map_columns(const RunPlan& plan) const;  ///< ⌈beads / stride⌉
    double map_bytes(const RunPlan& plan) const;    ///< the whole map: rows × columns × 8 [bytes]
  };
  EnergyMapObserver() = default;
  explicit EnergyMapObserver(const Settings& settings) : settings_(settings) {}
  /// Validates, then reserves the whole map (t and energy) before the run: InvalidInput naming
  /// `map_samples` when it cannot be allocated.
  std::vector<std::uint64_t> schedule(const RunPlan& plan) override;
  void observe(const Snapshot& now) override;
  const Settings& settings() const { return settings_; }

  std::vector<double> t;       ///< row times [s]
  std::vector<double> energy;  ///< rows × columns, row-major [J]; column c sums beads c·stride …
  std::size_t columns = 0;

 private:
  Settings settings_;
};

/// What g(ν) transforms (docs/physics.md, "Nonlinear dynamics"). The paper's is the displacement; after a velocity kick in the
/// sonic vacuum every bead the pulse has passed keeps a permanent displacement, a step in u_n(t)
/// whose power ∝ 1/ν² buries the vibrations under a peak at 0 Hz. The velocity is the step's
/// derivative (a pulse, white), so its spectrum shows the vibrations themselves.
enum class SpectrumSource { displacement, velocity };
SpectrumSource parse_spectrum_source(const std::string& name);  ///< "displacement" | "velocity"
std::string to_string(SpectrumSource source);

/// g(ν) = Σ_n |x̂_n(ν)|² / max_ν(…) of x = u (the paper's) or v over uniform samples of [0, T]
/// (spectral_density.hpp). Memory while it runs: N × samples doubles.
class SpectralDensityObserver final : public Observer {
 public:
  struct Settings {
    std::size_t samples = 2000;  ///< uniform samples 0 … T (≥ 2)
    SpectrumSource source = SpectrumSource::displacement;
    /// Throws InvalidInput naming `spectrum_samples`.
    void validate(const RunPlan& plan) const;
  };
  SpectralDensityObserver() = default;
  explicit SpectralDensityObserver(const Settings& settings) : settings_(settings) {}
  std::vector<std::uint64_t> schedule(const RunPlan& plan) override;
  void observe(const Snapshot& now) override;
  void finish(const Snapshot& at_T) override;
  const Settings& settings() const { return settings_; }

  std::vector<double> freq_khz;  ///< ν_j = j / (K Δt) [kHz], j = 0 … K/2
  std::vector<double> density;   ///< g(ν_j), max 1

 private:
  Settings settings_;
  std::vector<double> rows_;    // samples × N
  double sample_interval_ = 0;  // Δt [s]: the time of the second sample (the first is at 0)
};

/// The maximal Lyapunov exponent's finite-time estimate X1(t) = ln(‖w(t)‖/‖w(0)‖)/t [1/s] at the
/// energy spread's sample times, and the deviation vector's distribution along the chain (where
/// the chaos sits) at uniform times, from the tangent map the run carries
/// (IntegrationConfig::lyapunov; tangent_map.hpp). For a regular orbit X1 decays like ln t / t.
class LyapunovObserver final : public Observer {
 public:
  struct Settings {
    EnergySpreadObserver::Settings times{};  ///< X1 at the times these settings give m̃2
    std::size_t deviation_samples = 0;       ///< uniform times 0 … T of the distribution; 0 = none
    /// Throws InvalidInput naming `samples` … or `deviation_samples`.
    void validate(const RunPlan& plan) const;
  };
  LyapunovObserver() = default;
  explicit LyapunovObserver(const Settings& settings) : settings_(settings) {}
  std::vector<std::uint64_t> schedule(const RunPlan& plan) override;
  /// Throws InvalidInput naming `lyapunov` when the run carries no tangent map.
  void observe(const Snapshot& now) override;
  const Settings& settings() const { return settings_; }

  std::vector<double> t;            ///< times of X1 [s]
  std::vector<double> mle;          ///< X1(t) [1/s]
  std::vector<double> deviation_t;  ///< times of the distribution rows [s]
  std::vector<double> deviation;    ///< rows × N, row-major: share of ‖w‖² on each bead

 private:
  Settings settings_;
  std::vector<std::uint64_t> x1_steps_, deviation_steps_;
  std::size_t next_x1_ = 0, next_deviation_ = 0;
};

/// The state at T with its site energies and bead forces.
class FinalStateObserver final : public Observer {
 public:
  std::vector<std::uint64_t> schedule(const RunPlan&) override { return {}; }
  void observe(const Snapshot&) override {}
  void finish(const Snapshot& at_T) override;

  State state;                 ///< u [m], v [m/s] at T
  std::vector<double> energy;  ///< E_n(T) [J]
  std::vector<double> force;   ///< bead forces at T [N]
};

}  // namespace granular
