#pragma once
// One realization of the disordered Klein–Gordon chain (klein_gordon/klein_gordon.hpp) from its
// customary excitation, and an ensemble of them on threads: the library's entry point for DKG
// spreading and weak-chaos runs (Skokos, Krimer, Komineas & Flach, PRE 79, 056211 (2009);
// Senyange, Many Manda & Skokos, PRE 98, 052229 (2018)). Realization r is chain (seed, r) and,
// for a block, the signs of block_energy_kick(seed, r): a pure function of (config, r).
//
// The run is SABA2C (the field's scheme for DKG) at `time_step` in the model's units (time 1/ω₀,
// unit masses), the whole chain (no active window). Observables at each sample, from the site
// energies z_l = E_l / Σ E: m2 = Σ (l − l̄)² z_l about the centroid l̄ = Σ l z_l, and
// P = 1/Σ z_l²; with `mle`, the finite-time maximal Lyapunov exponent Λ(t) = X1(t) of the
// tangent map (deviation on the excited sites, norm with time_unit 1, renormalized every 10
// steps), whose orbit is the plain run's bit for bit.
//
// The ensemble stores each realization in its own slot and averages them in index order, so its
// means are bit-identical for any thread count (parallel_realizations.hpp).
//
//   granular::KleinGordonRunConfig c{.chain = {.N = 500, .W = 4}, .energy = 0.4,
//                                    .sample_steps = {5, 50, 500, 5000}};
//   auto e = granular::klein_gordon_ensemble(c, 8, 2);   // e.m2[s], e.mle[s] at e.time[s]
#include <cstddef>
#include <cstdint>
#include <vector>

#include "granular/klein_gordon/klein_gordon.hpp"

namespace granular {

struct KleinGordonRunConfig {
  KleinGordonParameters chain;              ///< N, W and seed; its `realization` is replaced by the run's
  double energy = 0.4;                      ///< single site: its energy E; block: the energy density h per site
  std::size_t block = 0;                    ///< 0: one site at the centre; L ≥ 1: L sites centred on it
  double time_step = 0.2;                   ///< τ [1/ω₀], > 0
  std::vector<std::uint64_t> sample_steps;  ///< steps from the start, increasing, at least one
  bool mle = true;                          ///< also the finite-time mLE Λ(t)
  /// Also the site energies E_l at every sample (KleinGordonRun::energy_map); an ensemble keeps
  /// realization 0's only. At most klein_gordon_energy_map_limit values (samples × N).
  bool energy_map = false;
};

/// The most values (samples × N) an energy map may hold: 2e8 doubles, 1.6 GB.
inline constexpr double klein_gordon_energy_map_limit = 2e8;

/// Throws InvalidInput naming `N`, `W`, `energy`, `block`, `time_step`, `sample_steps` or
/// `energy_map` (beyond its limit) unless `config` is one run_klein_gordon takes.
void validate(const KleinGordonRunConfig& config);

/// One realization's curves at the sample times.
struct KleinGordonRun {
  std::vector<double> time;           ///< [1/ω₀]
  std::vector<double> m2;             ///< about the centroid [sites²]
  std::vector<double> participation;  ///< P [sites]
  std::vector<double> mle;            ///< Λ(t) [ω₀]; empty without `mle`
  double max_energy_error = 0;        ///< max over samples of |H − H(0)| / H(0)
  /// With `energy_map`: E_l at sample s as energy_map[s N + l] (samples × N, row-major, l from 0):
  /// the site energies m2 and P are made of, each row summing to H but for the walls' halves of the
  /// two end bonds (observables.hpp: unowned_wall_energy, nil until the energy reaches an end);
  /// empty otherwise.
  std::vector<double> energy_map;
};

/// Realization `realization` of `config`. Throws as validate.
KleinGordonRun run_klein_gordon(const KleinGordonRunConfig& config, std::uint64_t realization);

/// Realizations 0 … count − 1 and their means (index order; bit-identical for any `threads`,
/// 0: resolve_threads' default). Throws as run_klein_gordon, and InvalidInput naming
/// `realizations` for count 0.
struct KleinGordonEnsemble {
  std::vector<double> time;
  std::vector<double> m2, participation, mle;  ///< means over the realizations
  std::vector<double> mean_log10_mle;          ///< ⟨log10 Λ⟩, as the field averages Λ; NaN if any Λ ≤ 0
  std::vector<KleinGordonRun> runs;            ///< each realization's, in index order
};
KleinGordonEnsemble klein_gordon_ensemble(const KleinGordonRunConfig& config, std::size_t count, int threads = 0);

}  // namespace granular
