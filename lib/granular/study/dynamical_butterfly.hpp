#pragma once
// The Hofstadter butterfly recovered from the dynamics (docs/physics.md, "Quasiperiodic chains";
// docs/quasiperiodic.md, "The butterfly from the dynamics"), as Martínez, Porter & Kevrekidis do on
// the cylinder chain: for each ratio β of a grid, the chain (the recipe with its ratio replaced, as
// compute_butterfly does) is started from a small random velocity of every bead, integrated by
// spread() (dynamics/spread.hpp), and the velocities' power summed over beads, g(ν), is taken by
// the SpectralDensityObserver. Its peaks are the chain's eigenfrequencies (study/butterfly.hpp).
//
// Why every bead, at random: a single kicked bead j excites mode k with weight w_kj², nothing for
// the modes localized away from j or with a node there; independent velocities v_n, uniform in
// [−a, a], give mode k (unit eigenvector w_k of M^{-1/2} K M^{-1/2}) the mean velocity weight
// Σ_n m_n w_kn² a²/3, m a²/3 for beads of one mass whatever the mode's shape, so every mode shows
// (one draw scatters the weights about that mean, as a squared Gaussian does). Why velocities: each mode's velocity power
// is then the same on average, a flat comb, where its displacement power would fall as 1/ω². Why small: a is chosen so
// that the energy stays far below what opens a contact (checked), the Hertz force then being its
// linearization to O(strain/overlap). The same velocities (one seed) start every β's chain.
//
//   granular::DynamicalButterflyConfig c;
//   c.chain.N = 100;
//   c.chain.source = granular::Quasiperiodic{.kind = granular::Quasiperiodic::Kind::cylinders, .modulation = 0.3};
//   c.ratios = {0.01, 0.02, …};
//   auto columns = granular::compute_dynamical_butterfly(c, {});
#include <cstdint>
#include <ostream>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/dynamics/observers.hpp"
#include "granular/dynamics/spread.hpp"
#include "granular/dynamics/state.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/model/chain_recipe.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

struct DynamicalButterflyConfig {
  ChainRecipe chain;           ///< a quasiperiodic recipe (chain.quasi set), F0 > 0; its ratio is replaced by each β
  std::vector<double> ratios;  ///< β values, each finite and > 0
  std::uint64_t realization = 0;    ///< which phase of chain.seed (or the given phase)
  double amplitude = 1e-5;          ///< a [m/s]: v_n(0) uniform in [−a, a], u_n(0) = 0
  std::uint64_t velocity_seed = 1;  ///< seed of the initial velocities (the same for every β)
  /// T [s] (frequency resolution 1/T), τ [s], force law, integrator. The active window is not
  /// used (every bead moves from t = 0).
  IntegrationConfig integration{};
  /// K uniform samples spanning [0, T] (K − 1 must divide T/τ): Δt = T/(K − 1), resolution
  /// 1/(K Δt) ≈ 1/T, Nyquist frequency 1/(2 Δt)
  std::size_t spectrum_samples = 2001;
  SpectrumSource source = SpectrumSource::velocity;
  double max_energy_error = 1e-3;  ///< guard on the relative energy error; 0 = unwatched
};

/// The meaning and units of the run's own settings (parameter_table.hpp): T and τ, the integrator
/// and force law (words), amplitude, velocity_seed, spectrum_samples, max_energy_error and
/// spectrum_of. Not the chain, ratios and realization (the chain's words are a front end's).
const ParameterTable<DynamicalButterflyConfig>& dynamical_butterfly_parameters();

/// Throws InvalidInput naming the field: quasi, ratios, F0, amplitude (zero, not finite, or an
/// energy that could open a contact of some β's chain), time_step (past the scheme's stability
/// limit on some β's chain), spectrum_samples (fewer than 2, K − 1 not dividing T/τ, or a Nyquist
/// frequency below that chain's highest frequency: the peaks would alias), duration, and the chain's
/// own fields.
void validate(const DynamicalButterflyConfig& config);

/// v_n(0) of every chain: a · (2U_n − 1), U_n the uniforms of RandomStream(velocity_seed, 0).
State random_velocities(std::size_t beads, double amplitude, std::uint64_t velocity_seed);

struct DynamicalButterflyColumn {
  double ratio = 0;
  std::vector<double> freq_khz;  ///< ν_j = j/(K Δt) [kHz], j = 0 … K/2 (the same for every β)
  std::vector<double> power;     ///< Σ_n |x̂_n(ν_j)|², normalized to max 1 (x = v by default)
  double initial_energy = 0;     ///< H(0) above the static state [J]
  double opening_energy = 0;     ///< the least energy that opens a contact of this chain [J]
  double max_energy_error = 0;   ///< the largest relative energy error of the run
};

/// One column per β, in the order given; thread-count invariant (one chain per β, fixed slots).
/// Throws InvalidInput (validate) before any run; NumericalError if a run fails its energy guard.
std::vector<DynamicalButterflyColumn> compute_dynamical_butterfly(const DynamicalButterflyConfig& config,
                                                                  const RunOptions& run);

/// ratio,freq_khz,power: one row per frequency per β.
void write_dynamical_butterfly_csv(std::ostream& out, const std::vector<DynamicalButterflyColumn>& columns);

/// The JSON entries: chain (its ratio "each of ratios"), ratios, realization, initial_state {kind,
/// amplitude_m_per_s, velocity_seed}, integration {duration_s, time_step_s, force_law, integrator},
/// spectrum {of, samples, resolution_khz, nyquist_khz}, and per ratio initial_energy_J,
/// energy_over_opening (H0 over the energy that opens a contact: ≪ 1 is linear) and max_energy_error.
nlohmann::json describe_dynamical_butterfly(const DynamicalButterflyConfig& config,
                                            const std::vector<DynamicalButterflyColumn>& columns);

}  // namespace granular
