#include "granular/dynamics/periodic_orbit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "granular/dynamics/detail/dense_lapack.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

double norm2(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v * v;
  return std::sqrt(s);
}

void check_frequency(double omega) {
  if (!(omega > 0) || !std::isfinite(omega)) throw InvalidInput("omega", ": the frequency must be finite and > 0");
}

}  // namespace

std::size_t shooting_steps(const Chain& chain, double omega) {
  check_frequency(omega);
  // Gershgorin on M^{-1} K: every eigenvalue ω² ≤ max_i 2 (B_i + B_{i+1}) / m_i.
  double omega_max = omega;
  if (chain.precompression > 0) {
    const auto b = linear_stiffness(chain);
    for (std::size_t i = 0; i < chain.size(); ++i)
      omega_max = std::max(omega_max, std::sqrt(2 * (b[i] + b[i + 1]) * chain.inverse_mass[i]));
  }
  const double steps = std::ceil(2 * std::numbers::pi * omega_max / (omega * 0.05));
  auto n = static_cast<std::size_t>(std::max(128.0, std::min(steps, 1e7)));
  return n + n % 2;
}

HalfPeriodMap half_period_map(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                              std::size_t steps_per_period, double omega, const std::vector<double>& x0, bool jacobian) {
  check_frequency(omega);
  const std::size_t n = chain.size();
  if (x0.size() != n) throw InvalidInput("guess", ": must have one displacement per bead");
  if (steps_per_period < 2 || steps_per_period % 2 != 0)
    throw InvalidInput("steps_per_period", " " + std::to_string(steps_per_period) + ": must be even and >= 2");
  const double tau = 2 * std::numbers::pi / omega / static_cast<double>(steps_per_period);
  State start(n);
  start.u = x0;
  std::vector<State> columns;
  if (jacobian) {
    columns.assign(n, State(n));
    for (std::size_t j = 0; j < n; ++j) columns[j].u[j] = 1;
  }
  const auto images = propagate_deviations(law, chain, scheme, tau, steps_per_period / 2, start, columns);
  HalfPeriodMap out;
  out.velocity = images.orbit.v;
  if (jacobian) {
    out.jacobian.resize(n * n);
    for (std::size_t j = 0; j < n; ++j)
      std::copy(images.deviations[j].v.begin(), images.deviations[j].v.end(), out.jacobian.begin() + j * n);
  }
  for (double v : out.velocity)
    if (!std::isfinite(v)) throw NumericalError("shooting: the orbit became non-finite");
  return out;
}

double relative_residual(const std::vector<double>& velocity, double omega, const std::vector<double>& x0) {
  const double scale = omega * norm2(x0);
  return scale > 0 ? norm2(velocity) / scale : std::numeric_limits<double>::infinity();
}

PeriodicOrbit find_periodic_orbit(const ForceLaw& law, const Chain& chain, double omega,
                                  const std::vector<double>& guess, const ShootingConfig& config) {
  check_frequency(omega);
  const std::size_t n = chain.size();
  if (n > config.max_dense_beads)
    throw InvalidInput("N", " " + std::to_string(n) + ": more beads than the dense shooting Jacobian allows (" +
                                std::to_string(config.max_dense_beads) + ")");
  if (guess.size() != n) throw InvalidInput("guess", ": must have one displacement per bead");
  const double guess_norm = norm2(guess);
  if (!(guess_norm > 0) || !std::isfinite(guess_norm))
    throw InvalidInput("guess", ": must be finite and not all zero (zero is the trivial orbit)");
  PeriodicOrbit orbit;
  orbit.omega = omega;
  orbit.period = 2 * std::numbers::pi / omega;
  orbit.steps_per_period = config.steps_per_period > 0 ? config.steps_per_period : shooting_steps(chain, omega);
  orbit.time_step = orbit.period / static_cast<double>(orbit.steps_per_period);
  orbit.scheme = config.scheme;
  orbit.x0 = guess;
  const auto map = [&](const std::vector<double>& x, bool jac) {
    return half_period_map(law, chain, config.scheme, orbit.steps_per_period, omega, x, jac);
  };

  auto current = map(orbit.x0, true);
  double r = relative_residual(current.velocity, omega, orbit.x0);
  orbit.residuals.push_back(r);
  const int nn = static_cast<int>(n);
  std::vector<int> pivots(n);
  while (r > config.tolerance) {
    if (orbit.iterations >= config.max_iterations)
      throw NumericalError("shooting: Newton did not converge in " + std::to_string(config.max_iterations) +
                           " iterations at " + format_number(omega / (2 * std::numbers::pi) / 1e3) +
                           " kHz (relative residual " + format_number(r) + ")");
    std::vector<double> step(current.velocity);
    for (double& s : step) s = -s;
    int one = 1, info = 0;
    dgesv_(&nn, &one, current.jacobian.data(), &nn, pivots.data(), step.data(), &nn, &info);
    if (info != 0)
      throw NumericalError("shooting: the Jacobian is singular at " +
                           format_number(omega / (2 * std::numbers::pi) / 1e3) +
                           " kHz (a linear mode at this frequency?)");
    double lambda = 1;
    std::vector<double> trial(n);
    bool accepted = false;
    for (int halving = 0; halving <= 10 && !accepted; ++halving, lambda /= 2) {
      for (std::size_t i = 0; i < n; ++i) trial[i] = orbit.x0[i] + lambda * step[i];
      const auto tried = map(trial, false);
      const double rt = relative_residual(tried.velocity, omega, trial);
      if (rt < r) {
        accepted = true;
        r = rt;
      }
    }
    if (!accepted)
      throw NumericalError("shooting: Newton stalled at relative residual " + format_number(r) + " at " +
                           format_number(omega / (2 * std::numbers::pi) / 1e3) + " kHz");
    orbit.x0 = trial;
    ++orbit.iterations;
    orbit.residuals.push_back(r);
    if (norm2(orbit.x0) < 1e-6 * guess_norm)
      throw NumericalError("shooting: Newton fell to the rest state (the trivial orbit) at " +
                           format_number(omega / (2 * std::numbers::pi) / 1e3) + " kHz");
    if (r > config.tolerance) current = map(orbit.x0, true);
  }
  return orbit;
}

PeriodicOrbit find_periodic_orbit_on_arc(const ForceLaw& law, const Chain& chain, const ArcPrediction& p,
                                         const ShootingConfig& config) {
  check_frequency(p.omega);
  const std::size_t n = chain.size();
  if (n > config.max_dense_beads)
    throw InvalidInput("N", " " + std::to_string(n) + ": more beads than the dense shooting Jacobian allows (" +
                                std::to_string(config.max_dense_beads) + ")");
  if (p.x.size() != n || p.tangent_x.size() != n)
    throw InvalidInput("guess", ": the prediction and its tangent must have one displacement per bead");
  if (config.steps_per_period == 0)
    throw InvalidInput("steps_per_period", ": must be set (fixed along the branch) for arclength continuation");
  if (!(p.x_scale > 0) || !(p.omega_scale > 0)) throw InvalidInput("guess", ": the scales must be > 0");
  const double guess_norm = norm2(p.x);
  if (!(guess_norm > 0) || !std::isfinite(guess_norm))
    throw InvalidInput("guess", ": must be finite and not all zero (zero is the trivial orbit)");
  const double xs = p.x_scale, ws = p.omega_scale;
  const auto map = [&](const std::vector<double>& x, double omega, bool jac) {
    return half_period_map(law, chain, config.scheme, config.steps_per_period, omega, x, jac);
  };
  // The arclength condition: the scaled correction from the prediction along the tangent.
  const auto along = [&](const std::vector<double>& x, double omega) {
    double s = p.tangent_omega * (omega - p.omega) / ws;
    for (std::size_t i = 0; i < n; ++i) s += p.tangent_x[i] * (x[i] - p.x[i]) / xs;
    return s;
  };
  const auto khz = [](double omega) { return format_number(omega / (2 * std::numbers::pi) / 1e3); };

  PeriodicOrbit orbit;
  orbit.scheme = config.scheme;
  orbit.steps_per_period = config.steps_per_period;
  orbit.x0 = p.x;
  double omega = p.omega;
  auto current = map(orbit.x0, omega, true);
  double r = relative_residual(current.velocity, omega, orbit.x0), c = along(orbit.x0, omega);
  orbit.residuals.push_back(r);
  const std::size_t m = n + 1;
  const int mm = static_cast<int>(m);
  std::vector<int> pivots(m);
  std::vector<double> a(m * m), step(m), trial(n);
  while (r > config.tolerance || std::abs(c) > config.tolerance) {
    if (orbit.iterations >= config.max_iterations)
      throw NumericalError("shooting: arclength Newton did not converge in " + std::to_string(config.max_iterations) +
                           " iterations near " + khz(omega) + " kHz (relative residual " + format_number(r) + ")");
    // The bordered system in scaled unknowns (δx/xs, δω/ωs), the shooting rows divided by ω xs.
    const double h = 1e-6 * omega;
    const auto up = map(orbit.x0, omega + h, false), down = map(orbit.x0, omega - h, false);
    const double row = 1 / (omega * xs);
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t i = 0; i < n; ++i) a[j * m + i] = current.jacobian[j * n + i] * xs * row;
      a[j * m + n] = p.tangent_x[j];
    }
    for (std::size_t i = 0; i < n; ++i) a[n * m + i] = (up.velocity[i] - down.velocity[i]) / (2 * h) * ws * row;
    a[n * m + n] = p.tangent_omega;
    for (std::size_t i = 0; i < n; ++i) step[i] = -current.velocity[i] * row;
    step[n] = -c;
    int one = 1, info = 0;
    dgesv_(&mm, &one, a.data(), &mm, pivots.data(), step.data(), &mm, &info);
    if (info != 0)
      throw NumericalError("shooting: the bordered arclength system is singular near " + khz(omega) + " kHz");
    const double merit = std::hypot(r, c);
    bool accepted = false;
    double lambda = 1, trial_omega = omega;
    for (int halving = 0; halving <= 10 && !accepted; ++halving, lambda /= 2) {
      for (std::size_t i = 0; i < n; ++i) trial[i] = orbit.x0[i] + lambda * step[i] * xs;
      trial_omega = omega + lambda * step[n] * ws;
      if (!(trial_omega > 0)) continue;
      const auto tried = map(trial, trial_omega, false);
      const double rt = relative_residual(tried.velocity, trial_omega, trial), ct = along(trial, trial_omega);
      if (std::hypot(rt, ct) < merit) {
        accepted = true;
        r = rt, c = ct;
      }
    }
    if (!accepted)
      throw NumericalError("shooting: arclength Newton stalled at relative residual " + format_number(r) + " near " +
                           khz(omega) + " kHz");
    orbit.x0 = trial;
    omega = trial_omega;
    ++orbit.iterations;
    orbit.residuals.push_back(r);
    if (norm2(orbit.x0) < 1e-6 * guess_norm)
      throw NumericalError("shooting: arclength Newton fell to the rest state (the trivial orbit) near " + khz(omega) +
                           " kHz");
    if (r > config.tolerance || std::abs(c) > config.tolerance) current = map(orbit.x0, omega, true);
  }
  orbit.omega = omega;
  orbit.period = 2 * std::numbers::pi / omega;
  orbit.time_step = orbit.period / static_cast<double>(orbit.steps_per_period);
  return orbit;
}

State turning_state(const PeriodicOrbit& orbit) {
  State s(orbit.x0.size());
  s.u = orbit.x0;
  return s;
}

}  // namespace granular
