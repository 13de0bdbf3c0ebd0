#include "granular/orbits/breather_branch.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "granular/detail/enum_names.hpp"
#include "granular/detail/euclidean_norm.hpp"
#include "granular/dynamics/detail/dense_lapack.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/error.hpp"
#include "granular/io/hdf5_file.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/number_format.hpp"
#include "granular/orbits/breather_crossing.hpp"

namespace granular {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;
double to_omega(double khz) { return two_pi * khz * 1e3; }
double to_khz(double omega) { return omega / two_pi / 1e3; }
// The largest arclength step: a 5 % change of (x0, ω_b) relative to the last point.
constexpr double max_arc = 0.05;

constexpr auto continuation_names =
    detail::enum_names<Continuation>("continuation",
                                     {{Continuation::natural, "natural"}, {Continuation::arclength, "arclength"}});

// The component of u̇(T/2) along the mode, per unit amplitude: its sign tells whether the seed
// aφ oscillates faster (> 0 below the mode for a softening chain) or slower than ω_b.
double mode_residual(const ForceLaw& law, const Chain& chain, const ShootingConfig& shooting, std::size_t steps,
                     double omega, const std::vector<double>& phi, double a) {
  std::vector<double> x(phi.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = a * phi[i];
  const auto map = half_period_map(law, chain, shooting.scheme, steps, omega, x, false);
  double s = 0;
  for (std::size_t i = 0; i < x.size(); ++i) s += phi[i] * map.velocity[i];
  return s / a;
}

// `khz`: the target when the point was asked for it, reported as given (ω_b = 2π·khz rounds, and
// back to kHz it need not be khz again: 8.0 returns as 7.999999999999999); NaN: ω_b/2π.
BreatherPoint make_point(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit,
                         const BreatherBranchConfig& c, double khz = std::numeric_limits<double>::quiet_NaN()) {
  BreatherPoint p;
  p.omega = orbit.omega;
  p.freq_khz = std::isnan(khz) ? to_khz(orbit.omega) : khz;
  p.energy = total_energy(law, chain, turning_state(orbit));
  for (std::size_t i = 0; i < orbit.x0.size(); ++i)
    if (std::abs(orbit.x0[i]) > p.amplitude) p.amplitude = std::abs(orbit.x0[i]), p.centre = i;
  p.iterations = orbit.iterations;
  p.residual = orbit.residual();
  p.residuals = orbit.residuals;
  p.newton = orbit.newton;
  p.krylov_iterations = orbit.krylov_iterations;
  p.floquet = floquet_stability(law, chain, orbit,
                                FloquetConfig{.tolerance = c.stability_tolerance,
                                              .method = c.floquet_method,
                                              .max_dense_beads = c.shooting.max_dense_beads,
                                              .multipliers = c.floquet_multipliers});
  p.verdict_trusted = chain.precompression > 0;  // F0 = 0: the map's verdict, not the orbit's
  p.open_fraction = open_fractions(law, chain, orbit);
  p.max_open_fraction = *std::max_element(p.open_fraction.begin(), p.open_fraction.end());
  p.x0 = orbit.x0;
  return p;
}

}  // namespace

Continuation parse_continuation(const std::string& name) { return continuation_names.parse(name); }
std::string to_string(Continuation continuation) { return std::string(continuation_names.name_of(continuation)); }

void validate(const BreatherBranchConfig& c) {
  validate(c.chain);
  const bool vacuum = !(c.chain.F0 > 0);
  const auto* quasi = c.chain.as<Quasiperiodic>();
  const bool springs = quasi && quasi->kind == Quasiperiodic::Kind::s1;
  if (vacuum && !springs)
    throw InvalidInput("F0",
                       " 0: the uncompressed Hertz chain has no breathers (James, Kevrekidis & Cuevas 2013); "
                       "give F0 > 0, or beads on on-site springs (quasi s1 with k0_n_per_m)");
  if (vacuum && c.law != ForceLawKind::hertz)
    throw InvalidInput("law", " " + to_string(c.law) + ": at F0 = 0 only hertz (the expansions need F0 > 0)");
  const auto n = static_cast<long>(c.chain.size());
  if (c.mode < 0 || c.mode > n)
    throw InvalidInput("mode", " " + std::to_string(c.mode) + ": must be 1 … N (" + std::to_string(n) + ")");
  if (c.site < 0 || c.site > n)
    throw InvalidInput("site", " " + std::to_string(c.site) + ": must be 1 … N (" + std::to_string(n) + ")");
  if (!vacuum && c.site != 0)
    throw InvalidInput("site", ": the on-site seed is for F0 = 0; at F0 > 0 seed from a mode (mode, near_khz)");
  if (vacuum && (c.mode != 0 || !std::isnan(c.near_khz)))
    throw InvalidInput(c.mode != 0 ? "mode" : "near_khz",
                       ": at F0 = 0 every linear mode is one bead's on-site oscillation; choose the bead (site)");
  for (const auto& [name, v] :
       {std::pair{"near_khz", c.near_khz}, {"start_khz", c.start_khz}, {"target_khz", c.target_khz}})
    if (!std::isnan(v) && !(v > 0 && std::isfinite(v))) throw InvalidInput(name, ": must be finite and > 0 [kHz]");
  if (!c.seed_profile.empty()) {
    if (c.seed_profile.size() != static_cast<std::size_t>(n))
      throw InvalidInput("seed_profile", ": " + std::to_string(c.seed_profile.size()) +
                                             " displacements for a chain of N = " + std::to_string(n));
    const double norm = detail::euclidean_norm(c.seed_profile);
    if (!(norm > 0) || !std::isfinite(norm))
      throw InvalidInput("seed_profile", ": must be finite and not all zero (zero is the rest state)");
    if (std::isnan(c.start_khz)) throw InvalidInput("start_khz", ": required with a seed profile (its frequency)");
    if (c.mode != 0 || !std::isnan(c.near_khz))
      throw InvalidInput("seed_profile", ": give either a seed profile or a seed mode (mode, near_khz), not both");
  }
  // Two seeds, or an offset from a seed with the start given: one would be silently ignored.
  if (c.mode != 0 && !std::isnan(c.near_khz))
    throw InvalidInput("near_khz",
                       ": give either a seed mode number (`mode`) or a frequency to seed from "
                       "(`near_khz`), not both");
  if (!std::isnan(c.start_khz) && c.start_offset != BreatherBranchConfig{}.start_offset)
    throw InvalidInput("start_offset",
                       ": takes effect only without `start_khz` (it places the first frequency "
                       "off the seed's), which is given");
  if (!vacuum && c.mode == 0 && std::isnan(c.near_khz) && std::isnan(c.start_khz))
    throw InvalidInput("mode", ": no seed: give a mode number, a frequency to seed from (near_khz) or start_khz");
  if (!c.seed_profile.empty() && c.site != 0)
    throw InvalidInput("seed_profile", ": give either a seed profile or a seed site, not both");
  if (!(c.step_khz >= 0) || !std::isfinite(c.step_khz)) throw InvalidInput("step_khz", ": must be finite and >= 0");
  if (!(c.start_offset > 0 && c.start_offset < 0.5)) throw InvalidInput("start_offset", ": must be in (0, 0.5)");
  if (c.max_points < 1) throw InvalidInput("max_points", ": must be >= 1");
  // Zero would ask Newton for an exact orbit (it never stops) and call every orbit with a rounded
  // |μ| = 1 + 1e-16 unstable; NaN would make every comparison false.
  if (!(c.shooting.tolerance > 0) || !std::isfinite(c.shooting.tolerance))
    throw InvalidInput("tolerance", " " + format_number(c.shooting.tolerance) + ": must be finite and > 0");
  if (!(c.stability_tolerance > 0) || !std::isfinite(c.stability_tolerance))
    throw InvalidInput("stability_tolerance", " " + format_number(c.stability_tolerance) + ": must be finite and > 0");
  const auto beads = static_cast<std::size_t>(n);
  uses_newton_krylov(beads, c.shooting);  // refuses dense Newton beyond the dense limit (arclength too)
  const bool arpack = c.floquet_method == FloquetMethod::arpack ||
                      (c.floquet_method == FloquetMethod::automatic && beads > c.shooting.max_dense_beads);
  if (arpack && (c.floquet_multipliers < 1 || c.floquet_multipliers > 2 * n - 3))
    throw InvalidInput("floquet_multipliers", " " + std::to_string(c.floquet_multipliers) + ": must be 1 ... 2N - 3 (" +
                                                  std::to_string(2 * n - 3) + ")");
}

std::vector<double> onsite_breather_seed(const Chain& chain, double omega, std::size_t site) {
  const std::size_t n = chain.size();
  if (chain.onsite.empty() || chain.precompression > 0)
    throw InvalidInput("F0", ": the on-site seed is for beads on on-site springs at F0 = 0");
  if (site >= n)
    throw InvalidInput("site", " " + std::to_string(site + 1) + ": must be 1 … N (" + std::to_string(n) + ")");
  const double w2 = omega * omega;
  const double detuning = chain.mass[site] * w2 - chain.onsite[site];  // [N/m]
  if (!(detuning > 0) || !std::isfinite(detuning))
    throw InvalidInput("start_khz",
                       " " + format_number(to_khz(omega)) + ": a breather on bead " + std::to_string(site + 1) +
                           " lies above its on-site frequency " +
                           format_number(to_khz(std::sqrt(chain.onsite[site] * chain.inverse_mass[site]))) + " kHz");
  // c = (2/π) ∫_0^{π/2} cos^{5/2}θ dθ, the integral (√π/2) Γ(7/4)/Γ(9/4).
  const double c = std::tgamma(1.75) / std::tgamma(2.25) / std::sqrt(std::numbers::pi);
  const auto phi = [](double d) { return std::sqrt(std::abs(d)) * d; };
  const auto slope = [](double d) { return 1.5 * std::sqrt(std::abs(d)); };
  // The uniform chain's profile and its Λ = 2 (1 − s_1)^{3/2} (ω_b² − k/m = Λ c A a^{1/2} / m), to a
  // few % (tests/orbits/breather_cradle_test.cpp solves it: Λ = 4.4537): Newton's first guess.
  constexpr std::array<double, 6> shape{1, -0.705, 0.237, -0.033, 0.0014, -1.2e-5};
  constexpr double lambda = 4.45;
  const double root = detuning / (c * lambda * 0.5 * (chain.contact[site] + chain.contact[site + 1]));
  std::vector<double> a(n, 0.0), g(n), trial(n), dl(n), d(n), du(n);
  for (std::size_t j = 0; j < shape.size(); ++j) {
    if (site + j < n) a[site + j] = root * root * shape[j];
    if (j <= site) a[site - j] = root * root * shape[j];
  }
  // G_i = (k_i − m_i ω²) a_i − c [A_i φ(a_{i−1} − a_i) − A_{i+1} φ(a_i − a_{i+1})], walls at rest.
  const auto misfit = [&](const std::vector<double>& x, std::vector<double>& out) {
    double worst = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double left = i > 0 ? x[i - 1] : 0.0, right = i + 1 < n ? x[i + 1] : 0.0;
      out[i] = (chain.onsite[i] - chain.mass[i] * w2) * x[i] -
               c * (chain.contact[i] * phi(left - x[i]) - chain.contact[i + 1] * phi(x[i] - right));
      worst = std::max(worst, std::abs(out[i]));
    }
    return worst;
  };
  const int nn = static_cast<int>(n), one = 1;
  double now = misfit(a, g);
  // Converged to 1e-12 of the on-site force's scale m ω² a (G is a difference of such terms).
  for (int iteration = 0; now > 1e-12 * chain.mass[site] * w2 * std::abs(a[site]); ++iteration) {
    if (iteration >= 60)
      throw NumericalError("breathers: the harmonic-balance seed on bead " + std::to_string(site + 1) +
                           " did not converge at " + format_number(to_khz(omega)) + " kHz");
    for (std::size_t i = 0; i < n; ++i) {
      const double left = i > 0 ? a[i - 1] : 0.0, right = i + 1 < n ? a[i + 1] : 0.0;
      d[i] = chain.onsite[i] - chain.mass[i] * w2 +
             c * (chain.contact[i] * slope(left - a[i]) + chain.contact[i + 1] * slope(a[i] - right));
      if (i + 1 < n) dl[i] = du[i] = -c * chain.contact[i + 1] * slope(a[i] - right);
      g[i] = -g[i];
    }
    int info = 0;
    dgtsv_(&nn, &one, dl.data(), d.data(), du.data(), g.data(), &nn, &info);
    if (info != 0)
      throw NumericalError("breathers: the harmonic-balance seed's Jacobian is singular at " +
                           format_number(to_khz(omega)) + " kHz");
    bool accepted = false;
    std::vector<double> next(n);
    for (double step = 1; step > 1e-3 && !accepted; step /= 2) {
      for (std::size_t i = 0; i < n; ++i) trial[i] = a[i] + step * g[i];
      const double tried = misfit(trial, next);
      if (tried < now) accepted = true, now = tried;
    }
    if (!accepted)
      throw NumericalError("breathers: the harmonic-balance seed on bead " + std::to_string(site + 1) + " stalled at " +
                           format_number(to_khz(omega)) + " kHz");
    std::swap(a, trial);
    std::swap(g, next);
  }
  return a;
}

std::vector<double> open_fractions(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit) {
  auto p =
      make_splitting_propagator(law, chain, orbit.scheme, orbit.time_step, turning_state(orbit), {.enabled = false});
  std::vector<double> open(chain.bonds(), 0.0);
  for (std::size_t s = 0; s < orbit.steps_per_period; ++s) {
    const auto u = p->displacement();
    for (std::size_t k = 0; k < open.size(); ++k)
      if (chain.overlap[k] + bond_strain(u, k) < 0) open[k] += 1;
    p->advance(1);
  }
  for (double& f : open) f /= static_cast<double>(orbit.steps_per_period);
  return open;
}

bool inside_linear_band(const std::vector<double>& f, double khz) {
  if (f.empty()) return false;
  if (khz <= f.front()) return true;  // the acoustic band starts at 0
  if (khz >= f.back()) return false;
  // A gap is a spacing more than 3 times both neighbouring spacings (near a band edge the modes
  // crowd, so a gap stands out however the spacing varies along the bands).
  const auto hi = static_cast<std::size_t>(std::upper_bound(f.begin(), f.end(), khz) - f.begin());
  const double gap = f[hi] - f[hi - 1];
  const double before = hi >= 2 ? f[hi - 1] - f[hi - 2] : 0.0;
  const double after = hi + 1 < f.size() ? f[hi + 1] - f[hi] : 0.0;
  return gap <= 3 * std::max(before, after);
}

BreatherBranch continue_breather(const BreatherBranchConfig& c,
                                 const std::function<void(const BreatherPoint&)>& progress) {
  validate(c);
  const Chain chain = c.chain.chain(c.realization);
  const ForceLaw law = make_force_law(c.law, chain);
  const std::size_t n = chain.size();
  BreatherBranch branch;
  // At F0 = 0 (validate: only on on-site springs) D is diagonal, its "modes" single beads.
  const bool vacuum = !(chain.precompression > 0);
  const DynamicalMatrix d = dynamical_matrix(chain);
  const Spectrum modes = spectrum(d, all_modes(), {.vectors = !vacuum});
  branch.linear_khz = modes.freq_khz;
  if (vacuum)  // issue 42, item 5; measured by Long_BreatherCradle.ClaimedInstabilityIsEachMapsButDoesNotConverge
    branch.verdict_untrusted_reason =
        "F0 = 0: every contact opens each period, and the Floquet verdict does not converge with the steps "
        "per period (at one point of the 21-bead cradle: max|mu| 1.0074 at 128, stable at 256, 2048 and 8192, "
        "up to 1 + 8e-4 in between, SABA2C and ABA864 alike), although a perturbation grows by the computed "
        "max|mu| under each step count's map: the verdict is the map's, not the orbit's (docs/breathers.md)";

  double down = vacuum ? -1.0 : 1.0, start_khz = c.start_khz, omega = 0;
  std::vector<double> x(n);
  std::size_t steps = 0;
  ShootingConfig shooting = c.shooting;
  if (!c.seed_profile.empty()) {
    // The user's state at rest is Newton's first guess at start_khz.
    branch.seed_khz = start_khz;
    if (!std::isnan(c.target_khz)) down = c.target_khz < start_khz ? 1.0 : -1.0;
    x = c.seed_profile;
    for (double v : x) branch.seed_amplitude = std::max(branch.seed_amplitude, std::abs(v));
    omega = to_omega(start_khz);
    steps = c.shooting.steps_per_period > 0 ? c.shooting.steps_per_period : shooting_steps(chain, omega);
    shooting.steps_per_period = steps;
  } else if (vacuum) {
    // F0 = 0 on on-site springs: the anti-continuum seed, one bead's on-site oscillation, dressed
    // by harmonic balance at the first frequency (start_offset above it: these breathers harden).
    const std::size_t j = c.site > 0 ? static_cast<std::size_t>(c.site - 1) : (n - 1) / 2;
    branch.seed_site = static_cast<long>(j + 1);
    branch.seed_khz = to_khz(std::sqrt(chain.onsite[j] * chain.inverse_mass[j]));
    start_khz = std::isnan(c.start_khz) ? branch.seed_khz * (1 + c.start_offset) : c.start_khz;
    down = !std::isnan(c.target_khz) && c.target_khz < start_khz ? 1.0 : -1.0;
    omega = to_omega(start_khz);
    steps = c.shooting.steps_per_period > 0 ? c.shooting.steps_per_period : shooting_steps(chain, omega);
    shooting.steps_per_period = steps;
    x = onsite_breather_seed(chain, omega, j);
    for (double v : x) branch.seed_amplitude = std::max(branch.seed_amplitude, std::abs(v));
  } else {
    // The seed mode.
    std::size_t j = 0;
    if (c.mode > 0) {
      j = static_cast<std::size_t>(c.mode - 1);
    } else {
      const double near = std::isnan(c.near_khz) ? c.start_khz : c.near_khz;
      if (std::isnan(c.near_khz) && inside_linear_band(branch.linear_khz, c.start_khz))
        throw InvalidInput("start_khz", " " + format_number(c.start_khz) +
                                            ": inside a linear band of the chain, where no breather is isolated; "
                                            "give a seed (mode or near_khz)");
      for (std::size_t k = 1; k < n; ++k)
        if (std::abs(modes.freq_khz[k] - near) < std::abs(modes.freq_khz[j] - near)) j = k;
    }
    branch.seed_mode = static_cast<long>(j + 1);
    branch.seed_khz = modes.freq_khz[j];
    std::vector<double> phi(n);
    double peak = 0;
    for (std::size_t i = 0; i < n; ++i) {
      phi[i] = modes.vector(j)[i] * d.inverse_sqrt_mass[i];
      peak = std::max(peak, std::abs(phi[i]));
    }
    for (double& x : phi) x /= peak;

    down = !std::isnan(c.target_khz) ? (c.target_khz < branch.seed_khz ? 1.0 : -1.0) : 1.0;
    // Start off the mode by start_offset, but by at most a quarter of the way to the next mode on
    // that side (near a band edge the modes crowd, and passing one is a resonance).
    // Near a band edge the neighbours on the far side matter too: the seed's nonlinear shift must
    // stay well below their distance, or the mode's shape is a poor guess.
    double shift = c.start_offset * branch.seed_khz;
    if (j > 0) shift = std::min(shift, (down > 0 ? 0.25 : 0.1) * (branch.seed_khz - modes.freq_khz[j - 1]));
    if (j + 1 < n) shift = std::min(shift, (down < 0 ? 0.25 : 0.1) * (modes.freq_khz[j + 1] - branch.seed_khz));
    start_khz = std::isnan(c.start_khz) ? branch.seed_khz - down * shift : c.start_khz;
    omega = to_omega(start_khz);
    steps = c.shooting.steps_per_period > 0 ? c.shooting.steps_per_period : shooting_steps(chain, omega);
    shooting.steps_per_period = steps;

    // The seed's amplitude: the smallest a at which the residual along the mode changes sign,
    // bracketed by doubling from 1e-6 of the smallest static overlap and refined by bisection.
    const double overlap = *std::min_element(chain.overlap.begin(), chain.overlap.end());
    double a_lo = 1e-6 * overlap, g_lo = mode_residual(law, chain, shooting, steps, omega, phi, a_lo);
    double a_hi = a_lo, g_hi = g_lo;
    while (g_hi * g_lo > 0 && a_hi < 10 * overlap) {
      a_lo = a_hi, g_lo = g_hi;
      a_hi *= 2;
      g_hi = mode_residual(law, chain, shooting, steps, omega, phi, a_hi);
    }
    if (g_hi * g_lo > 0)
      throw NumericalError("breathers: no periodic orbit of the shape of mode " + std::to_string(j + 1) + " (" +
                           format_number(branch.seed_khz) + " kHz) at " + format_number(start_khz) +
                           " kHz up to amplitude 10 static overlaps (the nonlinearity shifts it the other way?)");
    for (int i = 0; i < 30 && a_hi - a_lo > 1e-4 * a_hi; ++i) {
      const double a = (a_lo + a_hi) / 2, g = mode_residual(law, chain, shooting, steps, omega, phi, a);
      (g * g_lo > 0 ? a_lo : a_hi) = a;
      if (g * g_lo > 0) g_lo = g;
    }
    branch.seed_amplitude = (a_lo + a_hi) / 2;
    for (std::size_t i = 0; i < n; ++i) x[i] = branch.seed_amplitude * phi[i];
  }
  branch.steps_per_period = steps;
  PeriodicOrbit orbit = find_periodic_orbit(law, chain, omega, x, shooting);
  branch.points.push_back(make_point(law, chain, orbit, c,
                                     start_khz == c.target_khz ? start_khz : std::numeric_limits<double>::quiet_NaN()));
  if (progress) progress(branch.points.back());

  // Continuation with a secant predictor: natural-parameter (the next ω_b fixed) or, once two
  // points give a secant, pseudo-arclength (the next point on the hyperplane orthogonal to the
  // secant, in units of the last point's ‖x0‖ and ω_b), which passes folds in ω_b.
  const double target = c.target_khz;
  // Default steps: from the start's distance to the seed, growing to 2 % of the seed frequency.
  // From a seed profile: 0.1 % of the start frequency.
  const double first_step = c.step_khz > 0           ? c.step_khz
                            : c.seed_profile.empty() ? std::abs(branch.seed_khz - start_khz)
                                                     : 1e-3 * start_khz;
  double step = -down * first_step;  // kHz, signed
  const double min_step = 1e-4 * first_step, max_step = c.step_khz > 0 ? 8 * first_step : 0.02 * branch.seed_khz;
  double arc = 0, min_arc = 0;  // the arclength step (scaled), set from the first secant
  ShootingConfig follow = shooting;
  follow.max_iterations = std::min(shooting.max_iterations, 10);
  std::vector<double> previous;
  double previous_khz = 0, previous_omega = 0;
  // Reached by a step asked for the target itself, not by comparing frequencies (see make_point).
  bool at_target = start_khz == target;
  // Why the branch stops between the last point and f, if it does: a linear mode there that shares
  // the breather's beads, a resonance (a band, or a mode under it; modes localized elsewhere are
  // passed, orbits/breather_crossing.hpp). At F0 = 0 the modes are single beads (no vectors): every
  // on-site frequency stops it. Checked before a step and again where the arclength corrector landed.
  const auto crossing_stop = [&](double f) -> std::string {
    const BreatherPoint& from = branch.points.back();
    if (vacuum) {
      const bool crosses = std::any_of(branch.linear_khz.begin(), branch.linear_khz.end(),
                                       [&](double mode) { return (mode - f) * (mode - from.freq_khz) < 0; });
      return crosses ? "reached an on-site frequency near " + format_number(f) + " kHz" : "";
    }
    const auto crossing = blocking_crossing(modes, d, from.x0, from.freq_khz, f);
    return crossing ? describe(*crossing) : "";
  };
  const auto passes_target = [&](double f) {
    return !std::isnan(target) && (f - target) * (branch.points.back().freq_khz - target) <= 0;
  };
  while (true) {
    const BreatherPoint& last = branch.points.back();
    if (!c.through_opening && !vacuum && last.max_open_fraction > 0) {
      branch.stop_reason = "a contact opened (max open fraction " + format_number(last.max_open_fraction) + ")";
      break;
    }
    if (at_target) {
      branch.stop_reason = "target frequency reached";
      break;
    }
    if (branch.points.size() >= c.max_points) {
      branch.stop_reason = "max_points reached";
      break;
    }
    ArcPrediction arc_guess;
    bool on_arc = c.continuation == Continuation::arclength && !previous.empty();
    double next = last.freq_khz + step;
    if (on_arc) {
      arc_guess.x_scale = detail::euclidean_norm(last.x0);
      arc_guess.omega_scale = last.omega;
      arc_guess.tangent_x.resize(n);
      for (std::size_t i = 0; i < n; ++i) arc_guess.tangent_x[i] = (last.x0[i] - previous[i]) / arc_guess.x_scale;
      arc_guess.tangent_omega = (last.omega - previous_omega) / last.omega;
      const double length = std::hypot(detail::euclidean_norm(arc_guess.tangent_x), arc_guess.tangent_omega);
      on_arc = length > 0 && std::isfinite(length);  // two equal points give no tangent: a natural step
      if (on_arc) {
        for (double& t : arc_guess.tangent_x) t /= length;
        arc_guess.tangent_omega /= length;
        if (arc == 0) arc = length, min_arc = 1e-4 * length;
        arc_guess.x.resize(n);
        for (std::size_t i = 0; i < n; ++i)
          arc_guess.x[i] = last.x0[i] + arc * arc_guess.tangent_x[i] * arc_guess.x_scale;
        arc_guess.omega = last.omega * (1 + arc * arc_guess.tangent_omega);
        next = to_khz(arc_guess.omega);
      }
    }
    bool to_target = passes_target(next);
    if (to_target) next = target;
    if (const std::string stop = crossing_stop(next); !stop.empty()) {
      branch.stop_reason = stop;
      break;
    }
    // The natural step to `f` from the secant through the last two points (none while they
    // share a frequency: the extrapolation would divide by zero).
    const auto natural_step = [&](double f) {
      std::vector<double> guess = last.x0;
      const double span = last.freq_khz - previous_khz;
      if (!previous.empty() && span != 0)
        for (std::size_t i = 0; i < n; ++i) guess[i] += (f - last.freq_khz) / span * (last.x0[i] - previous[i]);
      return find_periodic_orbit(law, chain, to_omega(f), guess, follow);
    };
    try {
      if (on_arc && !to_target) {
        orbit = find_periodic_orbit_on_arc(law, chain, arc_guess, follow);
        // The corrector moves ω_b off the prediction checked above: check where it landed.
        next = to_khz(orbit.omega);
        if (passes_target(next)) {
          to_target = true;
          next = target;
          orbit = natural_step(next);
        }
      } else {
        orbit = natural_step(next);
      }
    } catch (const NumericalError& e) {
      const bool smallest = on_arc ? (arc /= 2) < min_arc : std::abs(step /= 2) < min_step;
      if (smallest) {
        branch.stop_reason = std::string("Newton failed with the smallest step: ") + e.what();
        break;
      }
      continue;
    }
    if (const std::string stop = crossing_stop(next); !stop.empty()) {  // where the corrector landed
      branch.stop_reason = stop;
      break;
    }
    previous = last.x0;
    previous_khz = last.freq_khz;
    previous_omega = last.omega;
    branch.points.push_back(
        make_point(law, chain, orbit, c, to_target ? target : std::numeric_limits<double>::quiet_NaN()));
    at_target = to_target;
    if (progress) progress(branch.points.back());
    if (orbit.iterations <= 3) {
      step = std::copysign(std::min(std::abs(step) * 1.5, max_step), step);
      arc = std::min(arc * 1.5, max_arc);
    }
  }
  return branch;
}

void write_breather_csv(std::ostream& out, const BreatherBranch& branch) {
  out << "omega_rad_s,freq_khz,energy_J,amplitude_m,centre,max_multiplier,stable,complete,verdict_trusted,"
         "newton_iterations,residual,max_open_fraction\n";
  for (const auto& p : branch.points)
    out << format_number(p.omega) << ',' << format_number(p.freq_khz) << ',' << format_number(p.energy) << ','
        << format_number(p.amplitude) << ',' << p.centre + 1 << ',' << format_number(p.floquet.max_modulus) << ','
        << (p.floquet.stable ? 1 : 0) << ',' << (p.floquet.complete ? 1 : 0) << ',' << (p.verdict_trusted ? 1 : 0)
        << ',' << p.iterations << ',' << format_number(p.residual) << ',' << format_number(p.max_open_fraction) << '\n';
}

std::unique_ptr<Hdf5File> write_breather_hdf5(const std::string& path, const BreatherBranch& b) {
  const std::size_t rows = b.points.size(), n = rows > 0 ? b.points.front().x0.size() : 0;
  std::size_t width = 0;  // 2N (dense), or the most multipliers ARPACK gave a point
  for (const auto& p : b.points) width = std::max(width, p.floquet.multipliers.size());
  std::vector<double> freq, omega, energy, x0, re, im, open;
  std::vector<std::uint64_t> trusted;
  for (const auto& p : b.points) {
    freq.push_back(p.freq_khz);
    trusted.push_back(p.verdict_trusted ? 1 : 0);
    omega.push_back(p.omega);
    energy.push_back(p.energy);
    x0.insert(x0.end(), p.x0.begin(), p.x0.end());
    for (const auto& mu : p.floquet.multipliers) re.push_back(mu.real()), im.push_back(mu.imag());
    re.resize(re.size() + width - p.floquet.multipliers.size(), std::numeric_limits<double>::quiet_NaN());
    im.resize(re.size(), std::numeric_limits<double>::quiet_NaN());
    open.insert(open.end(), p.open_fraction.begin(), p.open_fraction.end());
  }
  auto out = std::make_unique<Hdf5File>(path);
  Hdf5File& file = *out;
  file.write("freq_khz", freq);
  file.write("omega_rad_s", omega);
  file.write("energy_J", energy);
  file.write("verdict_trusted", trusted);
  file.write("x0", x0.data(), rows, n);
  file.write("multipliers_real", re.data(), rows, width);
  file.write("multipliers_imag", im.data(), rows, width);
  file.write("open_fraction", open.data(), rows, n + 1);
  file.write("linear_khz", b.linear_khz);
  file.attribute(
      "layout",
      "row j = point j of the branch (as in the CSV); x0: displacements [m] at the turning point "
      "(velocities 0); multipliers: the Floquet multipliers by modulus descending, all 2N (dense) or the largest "
      "(ARPACK, NaN-padded); open_fraction: "
      "per bond 0..N (walls included), the fraction of the period it is open; verdict_trusted: 1, or 0 where "
      "the multipliers and the verdict are the discretized map's, not the orbit's (F0 = 0; "
      "verdict_untrusted_reason says why)");
  file.attribute("stop_reason", b.stop_reason);
  file.attribute("verdict_untrusted_reason", b.verdict_untrusted_reason);
  return out;
}

nlohmann::json describe_breather_branch(const BreatherBranchConfig& c, const BreatherBranch& b) {
  nlohmann::json j;
  j["chain"] = describe(c.chain, c.chain.drawn() ? std::optional<std::uint64_t>(c.realization) : std::nullopt);
  j["force_law"] = to_string(c.law);
  j["seed"] = {{"mode", b.seed_mode}, {"linear_khz", b.seed_khz}, {"amplitude_m", b.seed_amplitude}};
  if (b.seed_mode == 0)
    j["seed"] = {{"profile", "given"}, {"start_khz", b.seed_khz}, {"amplitude_m", b.seed_amplitude}};
  if (b.seed_site > 0)
    j["seed"] = {{"site", b.seed_site},
                 {"onsite_khz", b.seed_khz},
                 {"profile", "harmonic balance at the first frequency (F0 = 0, on-site springs)"},
                 {"amplitude_m", b.seed_amplitude}};
  j["continuation"] = {{"method",
                        c.continuation == Continuation::natural
                            ? "natural-parameter in frequency, secant predictor, step halving/growth"
                            : "pseudo-arclength in (x0, frequency) scaled by the last point's norm and "
                              "frequency, secant predictor and tangent, step halving/growth (natural-parameter "
                              "for the second point and the step onto a target)"},
                       {"start_khz", b.points.empty() ? 0.0 : b.points.front().freq_khz},
                       {"target_khz", std::isnan(c.target_khz) ? nlohmann::json() : nlohmann::json(c.target_khz)},
                       {"max_points", c.max_points},
                       {"stop_at_opening", !c.through_opening && c.chain.F0 > 0},
                       {"stop_reason", b.stop_reason}};
  j["shooting"] = {{"scheme", c.shooting.scheme.name},
                   {"steps_per_period", b.steps_per_period},
                   {"tolerance", c.shooting.tolerance},
                   {"newton", b.points.empty() ? std::string() : b.points.front().newton},
                   {"newton_requested", to_string(c.shooting.newton)},
                   {"max_dense_beads", c.shooting.max_dense_beads},
                   {"residual", "||du/dt(T/2)|| / (omega_b ||x0||), half-period shooting from rest"}};
  j["stability_tolerance"] = c.stability_tolerance;
  j["floquet"] = {{"method", b.points.empty() ? std::string() : b.points.front().floquet.method},
                  {"method_requested", to_string(c.floquet_method)},
                  {"multipliers_requested", c.floquet_multipliers},
                  {"verdict_untrusted_reason",
                   b.verdict_untrusted_reason.empty() ? nlohmann::json() : nlohmann::json(b.verdict_untrusted_reason)}};
  nlohmann::json points = nlohmann::json::array();
  for (const auto& p : b.points)
    points.push_back({{"freq_khz", p.freq_khz},
                      {"newton_residuals", p.residuals},
                      {"krylov_iterations", p.krylov_iterations},
                      {"floquet_operator_applications", p.floquet.operator_applications},
                      {"arpack_restarts", p.floquet.restarts},
                      {"floquet_complete", p.floquet.complete},
                      {"verdict_trusted", p.verdict_trusted},
                      {"instability", p.floquet.instability},
                      {"growth_rate_per_s", p.floquet.growth_rate},
                      {"reciprocal_error", p.floquet.reciprocal_error},
                      {"product_error", p.floquet.product_error},
                      {"unit_pair_distance", p.floquet.unit_pair_distance},
                      {"ritz_residual", p.floquet.ritz_residual},
                      {"ritz_estimates", p.floquet.ritz_estimates}});
  j["points"] = points;
  return j;
}

}  // namespace granular
