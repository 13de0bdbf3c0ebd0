#pragma once
// A branch of breathers (time-periodic localized orbits) of one chain, continued in frequency
// from a linear mode (docs/breathers.md): seed, shooting (orbits/periodic_orbit.hpp), Floquet
// stability (orbits/floquet.hpp) and the contacts that open, point by point.
//
//   granular::BreatherBranchConfig c;
//   c.chain.source = granular::GivenTypes{.types = {1, 2, 1, 2, ...}};  // a diatomic chain
//   c.near_khz = 9.0;                          // seed: the linear mode nearest 9 kHz
//   c.target_khz = 8.0;                        // continue down into the gap
//   auto branch = granular::continue_breather(c);
//
// Continuation is natural-parameter in ω_b with a secant predictor and step control (a fold in ω_b
// stops the branch as a Newton failure), or pseudo-arclength (`Continuation::arclength`), which
// follows the branch through folds.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/dynamics/force_law.hpp"
#include "granular/io/hdf5_file.hpp"
#include "granular/model/chain_recipe.hpp"
#include "granular/orbits/floquet.hpp"
#include "granular/orbits/periodic_orbit.hpp"

namespace granular {

/// How the branch is followed: natural — the next point at a given ω_b (stops at a fold in ω_b);
/// arclength — pseudo-arclength in (x0, ω_b) after the first two points (passes folds).
enum class Continuation { natural, arclength };
Continuation parse_continuation(const std::string& name);  ///< "natural" | "arclength"
std::string to_string(Continuation continuation);

struct BreatherBranchConfig {
  /// F0 > 0: the seed is a linear mode. F0 = 0 only with on-site springs (quasi S1 with k0_n_per_m):
  /// the seed is then one bead's on-site oscillation (`site`) or a seed profile.
  ChainRecipe chain{};
  std::uint64_t realization = 0;  ///< of a drawn chain
  ForceLawKind law = ForceLawKind::hertz;
  long mode = 0;  ///< seed: linear mode number 1…N; 0: the mode nearest near_khz
  double near_khz = std::numeric_limits<double>::quiet_NaN();  ///< seed by frequency [kHz]
  /// First breather frequency [kHz]; NaN: the seed's frequency × (1 ∓ start_offset), towards target_khz
  /// (downwards without a target: the precompressed Hertz chain softens), but no further than a
  /// quarter of the way to the next mode on that side and a tenth of the distance to the other. Without mode and
  /// near_khz the seed is the mode nearest start_khz, which must then lie outside the linear bands.
  double start_khz = std::numeric_limits<double>::quiet_NaN();
  double start_offset = 1e-3;
  /// F0 = 0 (beads on on-site springs, touching without precompression): the bead 1…N the
  /// anti-continuum seed is centred on (0: the middle bead, (N + 1)/2). The first point lies
  /// start_offset above that bead's on-site frequency (breathers there harden: James, Kevrekidis &
  /// Cuevas, Physica D 251 (2013) 39) and is seeded from the harmonic-balance profile at it
  /// (onsite_breather_seed). Unused (must be 0) at F0 > 0.
  long site = 0;
  /// Seed from a state instead of a mode: N displacements [m] of a state at rest, Newton's first
  /// guess at start_khz (then required; mode and near_khz unset). Empty: seed from a mode.
  std::vector<double> seed_profile{};
  double target_khz = std::numeric_limits<double>::quiet_NaN();  ///< stop here [kHz]; NaN: no target
  double step_khz =
      0;  ///< first step [kHz] (sign ignored), growing to 8×; 0: the start's distance from the seed, growing to 2 % of it
  std::size_t max_points = 100;  ///< points on the branch
  /// Continue past points with an open contact (F0 > 0); without it the branch stops at the first
  /// (at F0 = 0 every contact opens: not read).
  bool through_opening = false;
  Continuation continuation = Continuation::natural;
  ShootingConfig shooting{};          ///< incl. newton: dense | krylov | auto (by N)
  double stability_tolerance = 1e-6;  ///< stable when max |μ| ≤ 1 + this
  /// Floquet multipliers: dense (all 2N), arpack (the floquet_multipliers of largest modulus) or
  /// auto (dense up to shooting.max_dense_beads, ARPACK beyond, within the dense method's cost
  /// where the dense fallback is affordable; floquet.hpp).
  FloquetMethod floquet_method = FloquetMethod::automatic;
  int floquet_multipliers = 16;
};

/// Throws InvalidInput naming the field (mode, near_khz, start_khz, target_khz, step_khz,
/// max_points, N, F0, site, law, seed_profile, floquet_multipliers, tolerance (shooting's),
/// stability_tolerance: both finite and > 0) before any work. N: dense Newton
/// (also for the arclength corrector) beyond shooting.max_dense_beads. F0: 0
/// without on-site springs (the uncompressed Hertz chain has no breathers: James et al. 2013).
void validate(const BreatherBranchConfig& config);

struct BreatherPoint {
  double omega = 0;                    ///< ω_b [rad/s]
  double freq_khz = 0;                 ///< ω_b/2π [kHz]
  double energy = 0;                   ///< H above the static state [J]
  double amplitude = 0;                ///< max |x0| [m]
  std::size_t centre = 0;              ///< bead of the largest |x0| (0-based)
  int iterations = 0;                  ///< Newton steps
  double residual = 0;                 ///< final relative residual
  std::vector<double> residuals;       ///< Newton history
  std::string newton;                  ///< "dense" or "krylov"
  std::vector<int> krylov_iterations;  ///< krylov: GMRES iterations per Newton step
  FloquetSpectrum floquet;
  /// false where floquet's verdict (stable, instability) belongs to the discretized map rather than
  /// to the orbit: at F0 = 0, where every contact opens each period, a perturbation does grow by
  /// the computed max |μ| under the map of that step count, but the verdict does not converge with
  /// the step count (docs/breathers.md, "Zero precompression": 1.0074 at 128 steps per period,
  /// stable at 256, 2048 and 8192, up to 1 + 8e-4 in between, for SABA2C and ABA864 alike).
  /// BreatherBranch::verdict_untrusted_reason says why.
  bool verdict_trusted = true;
  std::vector<double> open_fraction;  ///< per bond (N+1): fraction of the period with overlap < 0
  double max_open_fraction = 0;
  std::vector<double> x0;  ///< the profile at the turning point [m]
};

struct BreatherBranch {
  long seed_mode = 0;                ///< 1…N; 0: seeded from a profile or (F0 = 0) a site
  long seed_site = 0;                ///< F0 = 0: the bead 1…N the seed is centred on; 0 otherwise
  double seed_khz = 0;               ///< its linear frequency [kHz] (a profile's: start_khz; a site's: its on-site one)
  double seed_amplitude = 0;         ///< amplitude [m] of the first point's seed
  std::size_t steps_per_period = 0;  ///< of the first point
  std::vector<double> linear_khz;    ///< every linear mode [kHz], ascending
  std::vector<BreatherPoint> points;
  std::string stop_reason;  ///< why the branch ended
  /// Why the points' Floquet verdicts are untrusted (BreatherPoint::verdict_trusted); empty when
  /// they are trusted.
  std::string verdict_untrusted_reason;
};

/// The harmonic-balance breather of a chain at F0 = 0 on on-site springs k_n, centred on bead
/// `site` (0-based) at ω_b = `omega` [rad/s]: the fundamental amplitudes a_n [m] (u_n ≈ a_n cos ω_b t)
/// solving (k_n − m_n ω_b²) a_n = c [A_n φ(a_{n−1} − a_n) − A_{n+1} φ(a_n − a_{n+1})], φ(d) = |d|^{1/2} d,
/// c = (2/π) ∫_0^{π/2} cos^{5/2} θ dθ (the first Fourier coefficient of a one-sided Hertz contact,
/// which pushes only while compressed), walls at rest. Leading order in the amplitude: the
/// neighbours move against the centre (−0.705, 0.237, −0.033 of it in a uniform chain) and
/// ω_b² − k/m ∝ a^{1/2}. Solved by Newton (tridiagonal) from that uniform shape. Throws InvalidInput
/// (no on-site springs, F0 > 0, site, omega not above bead site's on-site frequency) or NumericalError.
std::vector<double> onsite_breather_seed(const Chain& chain, double omega, std::size_t site);

/// The per-bond fraction of one period of `orbit` during which the bond's overlap Δ_k + x_k < 0.
std::vector<double> open_fractions(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit);

/// True when f [kHz] lies between two consecutive linear frequencies closer than 3 × their median
/// spacing, or below the lowest: inside a band of the finite chain rather than in a gap or above.
bool inside_linear_band(const std::vector<double>& linear_khz, double khz);

/// The branch. `progress`, if set, is called after every point. Throws InvalidInput (bad config,
/// start inside a band without a seed) or NumericalError (no breather at the first frequency).
BreatherBranch continue_breather(const BreatherBranchConfig& config,
                                 const std::function<void(const BreatherPoint&)>& progress = {});

/// CSV: omega_rad_s,freq_khz,energy_J,amplitude_m,centre,max_multiplier,stable,complete,
/// verdict_trusted,newton_iterations,residual,max_open_fraction (one row per point). stable is 1
/// only from a complete set of multipliers (FloquetSpectrum::stable); complete 0: ARPACK's verdict
/// on part of the largest multipliers (unstable, or unknown); verdict_trusted 0: stable and
/// max_multiplier are the discretized map's, not the orbit's (BreatherPoint::verdict_trusted; F0 = 0).
void write_breather_csv(std::ostream& out, const BreatherBranch& branch);

/// HDF5 of the branch (one row per point): freq_khz, omega_rad_s, energy_J; verdict_trusted (uint64 1 or 0,
/// as the CSV's column); x0 (points × N, the turning-point profiles [m]); multipliers_real and multipliers_imag
/// (points × 2N, by |μ| descending; ARPACK: points × the most multipliers of a point, NaN-padded); open_fraction
/// (points × (N+1), per bond); linear_khz (N); string attributes layout, stop_reason and verdict_untrusted_reason
/// (BreatherBranch's; "" when every verdict is trusted). Written under its temporary name and returned
/// uncommitted, for RunMetadata::write to put in place after the JSON; throws IoError.
std::unique_ptr<Hdf5File> write_breather_hdf5(const std::string& path, const BreatherBranch& branch);

/// The JSON entries of a branch run: parameters (chain, seed, continuation, shooting) and results
/// (stop reason, points' Newton histories and multiplier checks).
nlohmann::json describe_breather_branch(const BreatherBranchConfig& config, const BreatherBranch& branch);

}  // namespace granular
